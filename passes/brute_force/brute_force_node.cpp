#include "brute_force_node.h"

#include "shared/pass_helpers.h"
#include "shared/pixel_march.h"

namespace ls {

rg::ImageRef addBruteForce(rg::RenderGraph& graph, const BruteForceInputs& in) {
    rg::ImageRef lin = graph.createImage("in-scattering (screen)",
                                         rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    auto pass = graph.addPass("brute-force ray march", rg::PassType::Graphics);
    const rg::BindingTable table = declarePixelMarch(pass, in.chain, in.light);
    // Cleared, and marched only within the light's screen rectangle: a small spot costs its
    // pixels, not the screen's.
    lin = pass.colorAttachment(lin, rg::LoadOp::Clear);
    pass.execute([shared = in.chain.shared, spec = in.chain.spec, values = in.chain.values,
                  table](rg::PassContext& ctx) {
        if (!scissorToLight(ctx, values)) return;
        drawPixelMarch(ctx, shared, spec, table, {.pipeline = "brute-force ray march"});
    });
    return lin;
}

}  // namespace ls
