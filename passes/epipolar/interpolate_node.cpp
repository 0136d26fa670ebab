#include "epipolar_nodes.h"
#include "interpolate_frag.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"

namespace ls {

rg::ImageRef addInterpolate(rg::RenderGraph& g, const InterpolateInputs& in,
                            const EpipolarSizes& s) {
    rg::ImageRef interpolated =
        g.createImage("in-scattering (all samples)",
                      rg::ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, s.samples, s.slices));
    auto pass = g.addPass("interpolate in-scattering", rg::PassType::Graphics);
    rg::BindingTable table(pass);
    table
        .sampled(LS_BINDING_INTERPOLATION_SOURCE, in.interpolationSource,
                 samplersOf(in.chain.shared).nearest())
        .sampled(LS_BINDING_INTERPOLATE_MARCHED, in.marched, samplersOf(in.chain.shared).nearest());
    pass.stencilTest(in.epipolarStencil);
    interpolated = pass.colorAttachment(interpolated, rg::LoadOp::Clear);
    pass.execute([shared = in.chain.shared, table](rg::PassContext& ctx) {
        auto desc = fullscreenPipeline(rg::spirv(ls_spirv::interpolate_frag), ctx, table.layout());
        desc.stencilTest = true;  // every valid sample: 1 <= stencil
        desc.stencil = {VK_STENCIL_OP_KEEP,
                        VK_STENCIL_OP_KEEP,
                        VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_LESS_OR_EQUAL,
                        0xff,
                        0,
                        1};
        const auto& p = shared->pipelines.graphics("interpolate in-scattering", desc);
        p.bind(ctx.cmd());
        ctx.vk().CmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return interpolated;
}

}  // namespace ls
