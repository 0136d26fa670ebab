#include "epipolar_nodes.h"
#include "refine_on_inscattering_frag.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"

namespace ls {

// One draw over the samples, no attachment; the shader rewrites the sources of the samples to march
// (see refine_on_inscattering.frag).
rg::ImageRef addRefineOnInscattering(rg::RenderGraph& g, const RefineOnInscatteringInputs& in,
                                     const EpipolarSizes& s) {
    auto pass = g.addPass("refine on in-scattering differences", rg::PassType::Graphics);
    rg::BindingTable table = epipolarTable(pass, in.chain, in.epipolar);
    const auto& sm = samplersOf(in.chain.shared);
    table.sampled(LS_BINDING_REFINE_MARCHED, in.marched, sm.nearest())
        .sampled(LS_BINDING_SOURCES_EPIPOLAR_Z, in.epipolarZ, sm.nearest());
    const rg::ImageRef sources =
        table.storageReadWrite(LS_BINDING_REFINE_LIN_SOURCES, in.interpolationSource);
    pass.renderArea({s.samples, s.slices});
    pass.execute([shared = in.chain.shared, table](rg::PassContext& ctx) {
        rg::GraphicsPipelineDesc desc = fullscreenPipeline(
            rg::spirv(ls_spirv::refine_on_inscattering_frag), ctx, table.layout());
        const auto& p = shared->pipelines.graphics("refine on in-scattering differences", desc);
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return sources;
}

}  // namespace ls
