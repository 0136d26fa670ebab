#include "shared/pass_helpers.h"
#include "epipolar_nodes.h"
#include "mark_ray_march_frag.h"

namespace ls {

// Valid samples carry stencil 1; the ray-marching ones among them are raised to 2.
void addMarkRayMarchSamples(rg::RenderGraph& g, const NodeInputs& in, EpipolarTextures& t) {
    auto pass = g.addPass("mark ray-marching samples", rg::PassType::Graphics);
    pass.sampled(t.interpolationSource);
    t.epipolarStencil = pass.stencilWrite(t.epipolarStencil, rg::LoadOp::Load);
    const EpipolarTextures tex = t;
    pass.execute([in, tex](rg::PassContext& ctx) {
        rg::GraphicsPipelineDesc desc = fullscreenPipeline(
            rg::spirv(ls_spirv::mark_ray_march_frag), ctx, {sampledBinding(0)});
        desc.stencilTest = true;
        desc.stencil = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_INCREMENT_AND_CLAMP, VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_EQUAL, 0xff, 0xff, 1};
        const auto& p = in.shared->pipelines.graphics(pipelineKey("mark ray-marching samples", ctx), desc);
        p.bind(ctx.cmd());
        vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
        rg::DescriptorPush()
            .sampled(0, ctx.view(tex.interpolationSource), ctx.layout(tex.interpolationSource),
                     in.shared->samplers.nearest())
            .push(ctx.device(), ctx.cmd(), p);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
}

}  // namespace ls
