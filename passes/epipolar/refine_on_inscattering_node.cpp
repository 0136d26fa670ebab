#include "epipolar_nodes.h"
#include "refine_on_inscattering_frag.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"

namespace ls {

// One draw over the valid samples (stencil != 0); the shader keeps the fragments whose stencil
// must rise (see refine_on_inscattering.frag) and discards the rest.
RefinedSamples addRefineOnInscattering(rg::RenderGraph& g, const RefineOnInscatteringInputs& in) {
    auto pass = g.addPass("refine on in-scattering differences", rg::PassType::Graphics);
    rg::BindingTable table = epipolarTable(pass, in.chain, in.epipolar);
    table.sampled(LS_BINDING_REFINE_MARCHED, in.marched, samplersOf(in.chain.shared).nearest());
    RefinedSamples out;
    out.interpolationSource =
        table.storageReadWrite(LS_BINDING_REFINE_LIN_SOURCES, in.interpolationSource);
    out.epipolarStencil = pass.stencilWrite(in.epipolarStencil, rg::LoadOp::Load);
    pass.execute([shared = in.chain.shared, table](rg::PassContext& ctx) {
        rg::GraphicsPipelineDesc desc = fullscreenPipeline(
            rg::spirv(ls_spirv::refine_on_inscattering_frag), ctx, table.layout());
        desc.stencilTest = true;  // every valid sample: 0 != stencil
        desc.stencil = {VK_STENCIL_OP_KEEP,
                        VK_STENCIL_OP_INCREMENT_AND_CLAMP,
                        VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_NOT_EQUAL,
                        0xff,
                        0xff,
                        0};
        const auto& p = shared->pipelines.graphics("refine on in-scattering differences", desc);
        p.bind(ctx.cmd());
        ctx.vk().CmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 0);
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return out;
}

}  // namespace ls
