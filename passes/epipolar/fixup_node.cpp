#include "epipolar_nodes.h"
#include "epipolar_shaders.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"
#include "shared/pixel_march.h"

namespace ls {

// Pixels the unwarp could not interpolate (stencil 0; it marked the rest) are ray-marched on their
// own, without trees, and composited into the engine's color like the unwarp's.
CompositeOutputs addFixup(rg::RenderGraph& g, const FixupInputs& in) {
    auto pass = g.addPass("fix-up ray march", rg::PassType::Graphics);
    const bool addOnly = in.target.addOnly;
    rg::BindingTable table =
        declarePixelMarch(pass, in.chain, in.light, addOnly ? kVertexAndFragmentStages : 0);
    // A later light draws the unwarp's wedge (its vertex shader reads the lines' window).
    if (addOnly)
        table.uniform(LS_BINDING_EPIPOLAR, in.epipolar.constants, kVertexAndFragmentStages);
    pass.stencilTest(in.cameraStencil);
    const CompositeOutputs written = addCompositeTarget(table, in.target);
    pass.execute([frame = in.chain, table, written, addOnly](rg::PassContext& ctx) {
        // A later light's unwarp kept to its screen rectangle: outside it nothing is added.
        if (addOnly && !scissorToLight(ctx, frame.values)) return;
        // The cap is a setting, read per frame like the other constants.
        const auto maxSteps =
            static_cast<uint32_t>(epipolarFrameOf(ctx.data(frame.values)).constants.marching.w);
        drawPixelMarch(ctx, frame.shared, frame.spec, table,
                       {.pipeline = "fix-up",
                        .maxSteps = maxSteps,
                        .whereStencilIsZero = true,
                        .composite = &written,
                        .addOnly = addOnly,
                        .vertex = addOnly ? windowWedgeShader() : rg::ShaderCode{},
                        .vertices = addOnly ? kWedgeVertices : 3});
    });
    return written;
}

}  // namespace ls
