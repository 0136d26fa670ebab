#include "shared/pass_helpers.h"
#include "epipolar_nodes.h"
#include "interpolate_frag.h"

namespace ls {

void addInterpolate(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                    EpipolarTextures& t) {
    t.interpolated = g.createImage("in-scattering (all samples)",
                                   rg::ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, s.samples, s.slices));
    auto pass = g.addPass("interpolate in-scattering", rg::PassType::Graphics);
    pass.sampled(t.interpolationSource);
    pass.sampled(t.marched);
    pass.stencilTest(t.epipolarStencil);
    t.interpolated = pass.colorAttachment(t.interpolated, rg::LoadOp::Clear);
    const EpipolarTextures tex = t;
    pass.execute([in, tex](rg::PassContext& ctx) {
        auto desc = fullscreenPipeline(rg::spirv(ls_spirv::interpolate_frag), ctx,
                                       {sampledBinding(0), sampledBinding(1)});
        desc.stencilTest = true;  // every valid sample: 1 <= stencil
        desc.stencil = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_LESS_OR_EQUAL, 0xff, 0, 1};
        const auto& p = in.shared->pipelines.graphics(pipelineKey("interpolate in-scattering", ctx), desc);
        p.bind(ctx.cmd());
        vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
        rg::DescriptorPush()
            .sampled(0, ctx.view(tex.interpolationSource), ctx.layout(tex.interpolationSource),
                     in.shared->samplers.nearest())
            .sampled(1, ctx.view(tex.marched), ctx.layout(tex.marched), in.shared->samplers.nearest())
            .push(ctx.device(), ctx.cmd(), p);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
}

}  // namespace ls
