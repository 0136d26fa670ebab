#include "brute_force_node.h"

#include "shared/pixel_march.h"

namespace ls {

rg::ImageRef addBruteForce(rg::RenderGraph& graph, const BruteForceInputs& in) {
    rg::ImageRef lin = graph.createImage("in-scattering (screen)",
                                         rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    auto pass = graph.addPass("brute-force ray march", rg::PassType::Graphics);
    const rg::BindingTable table = declarePixelMarch(pass, in.frame, in.light);
    lin = pass.colorAttachment(lin, rg::LoadOp::DontCare);
    pass.execute([shared = in.frame.shared, spec = in.frame.spec, table](rg::PassContext& ctx) {
        drawPixelMarch(ctx, shared, spec, table, {.pipeline = "brute-force ray march"});
    });
    return lin;
}

}  // namespace ls
