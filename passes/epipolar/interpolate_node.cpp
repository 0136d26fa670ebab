#include "shared/pass_helpers.h"
#include "epipolar_nodes.h"
#include "interpolate_frag.h"

namespace ls {

rg::ImageRef addInterpolate(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                            rg::ImageRef interpolationSource, rg::ImageRef marched,
                            rg::ImageRef epipolarStencil) {
    rg::ImageRef interpolated = g.createImage(
        "in-scattering (all samples)",
        rg::ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, s.samples, s.slices));
    auto pass = g.addPass("interpolate in-scattering", rg::PassType::Graphics);
    pass.sampled(interpolationSource);
    pass.sampled(marched);
    pass.stencilTest(epipolarStencil);
    interpolated = pass.colorAttachment(interpolated, rg::LoadOp::Clear);
    pass.execute([in, interpolationSource, marched](rg::PassContext& ctx) {
        auto desc = fullscreenPipeline(rg::spirv(ls_spirv::interpolate_frag), ctx,
                                       {sampledBinding(0), sampledBinding(1)});
        desc.stencilTest = true;  // every valid sample: 1 <= stencil
        desc.stencil = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_LESS_OR_EQUAL, 0xff, 0, 1};
        const auto& p = in.shared->pipelines.graphics(pipelineKey("interpolate in-scattering", ctx), desc);
        p.bind(ctx.cmd());
        vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
        rg::DescriptorPush()
            .sampled(0, ctx.view(interpolationSource), ctx.layout(interpolationSource),
                     in.shared->samplers.nearest())
            .sampled(1, ctx.view(marched), ctx.layout(marched), in.shared->samplers.nearest())
            .push(ctx.device(), ctx.cmd(), p);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return interpolated;
}

}  // namespace ls
