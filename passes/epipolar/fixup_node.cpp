#include "epipolar_nodes.h"
#include "shared/pixel_march.h"

namespace ls {

// Pixels the unwarp could not interpolate (stencil 1) are ray-marched on their own, without trees.
rg::ImageRef addFixup(rg::RenderGraph& g, const NodeInputs& in,
                      rg::ImageRef cameraStencil, rg::ImageRef screenInscatter) {
    auto pass = g.addPass("fix-up ray march", rg::PassType::Graphics);
    declarePixelMarch(pass, in);
    pass.stencilTest(cameraStencil);
    const rg::ImageRef out = pass.colorAttachment(screenInscatter, rg::LoadOp::Load);
    pass.execute([in](rg::PassContext& ctx) {
        // The cap is a setting, read per frame like the other constants.
        const auto maxSteps = static_cast<uint32_t>(in.shared->constants.epipolar2.y);
        drawPixelMarch(ctx, in,
                       {.pipeline = "fix-up", .maxSteps = maxSteps, .whereStencilIsOne = true});
    });
    return out;
}

}  // namespace ls
