#include "epipolar_nodes.h"
#include "mark_ray_march_frag.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"

namespace ls {

// Valid samples carry stencil 1; the ray-marching ones among them are raised to 2.
rg::ImageRef addMarkRayMarchSamples(rg::RenderGraph& g, const MarkRayMarchInputs& in) {
    auto pass = g.addPass("mark ray-marching samples", rg::PassType::Graphics);
    rg::BindingTable table(pass);
    table.sampled(LS_BINDING_INTERPOLATION_SOURCE, in.interpolationSource,
                  samplersOf(in.chain.shared).nearest());
    const rg::ImageRef marked = pass.stencilWrite(in.epipolarStencil, rg::LoadOp::Load);
    pass.execute([shared = in.chain.shared, table](rg::PassContext& ctx) {
        rg::GraphicsPipelineDesc desc =
            fullscreenPipeline(rg::spirv(ls_spirv::mark_ray_march_frag), ctx, table.layout());
        desc.stencilTest = true;
        desc.stencil = {VK_STENCIL_OP_KEEP,
                        VK_STENCIL_OP_INCREMENT_AND_CLAMP,
                        VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_EQUAL,
                        0xff,
                        0xff,
                        1};
        const auto& p = shared->pipelines.graphics("mark ray-marching samples", desc);
        p.bind(ctx.cmd());
        ctx.vk().CmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return marked;
}

}  // namespace ls
