#include "screen_lin_node.h"

#include <utility>

namespace ls {

rg::ImageRef addScreenLinNode(rg::RenderGraph& graph, const Shared& shared, const ScatterSpec& spec,
                              ScreenLinNode node) {
    rg::ImageRef lin = graph.createImage("in-scattering (screen)",
                                         rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    auto pass = graph.addPass(node.name, rg::PassType::Graphics);
    rg::BindingTable table = frameTable(pass, node.constants);
    table.sampled(LS_BINDING_DEPTH, node.depth, samplersOf(shared).nearest(),
                  VK_IMAGE_ASPECT_DEPTH_BIT);
    if (node.rows) node.rows(table);
    // Cleared, and drawn only within the light's screen rectangle: a light covering a corner of
    // the screen costs that corner.
    lin = pass.colorAttachment(lin, rg::LoadOp::Clear);
    pass.execute([shared, spec, table, node = std::move(node)](rg::PassContext& ctx) {
        if (!scissorToLight(ctx, node.values)) return;
        auto desc = fullscreenPipeline(node.shader(spec), ctx, table.layout());
        desc.specialization = spec.constants();
        if (node.specialize) node.specialize(desc.specialization);
        const auto& p = shared->pipelines.graphics(node.name, desc);
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return lin;
}

}  // namespace ls
