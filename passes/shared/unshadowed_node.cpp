#include "pixel_march.h"
#include "screen_lin_node.h"
#include "shader_variant.h"
#include "shared_nodes.h"
#include "shared_shaders.h"
#include "unshadowed_frag_variants.h"

namespace ls {

rg::ShaderCode unshadowedShader(const ScatterSpec& spec) {
    return pickShader(ls_spirv::unshadowed_frag_variants,
                      {{"LS_NEEDS_TABLE", spec.light != LightType::Directional}});
}

namespace {

// An unshadowed light with a light color: the color varies along each ray, which no closed form
// over the ray carries, so each pixel marches it as brute force marches a shadow map (one step per
// texel of the color, the visibility 1), the steps integrated in closed form between them.
rg::ImageRef addColoredUnshadowed(rg::RenderGraph& graph, const UnshadowedInputs& in) {
    rg::ImageRef lin = graph.createImage("in-scattering (screen)",
                                         rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    auto pass = graph.addPass("unshadowed light-color march", rg::PassType::Graphics);
    LightImages light = in.light;
    light.shadowMap = {};
    const rg::BindingTable table = declarePixelMarch(pass, in.chain, light);
    // Cleared, and marched only within the light's screen rectangle.
    lin = pass.colorAttachment(lin, rg::LoadOp::Clear);
    pass.execute([shared = in.chain.shared, spec = in.chain.spec, values = in.chain.values,
                  table](rg::PassContext& ctx) {
        if (!scissorToLight(ctx, values)) return;
        drawPixelMarch(ctx, shared, spec, table, {.pipeline = "unshadowed light-color march"});
    });
    return lin;
}

}  // namespace

rg::ImageRef addUnshadowed(rg::RenderGraph& graph, const UnshadowedInputs& in) {
    if (in.light.lightColor.valid()) return addColoredUnshadowed(graph, in);
    return addScreenLinNode(
        graph, in.chain.shared, in.chain.spec,
        {.name = "unshadowed in-scattering",
         .constants = in.chain.constants,
         .depth = in.chain.depth,
         .values = in.chain.values,
         // The table; an unshadowed frame has nothing else.
         .rows =
             [in](rg::BindingTable& table) { addMarchInputs(table, in.chain.shared, in.light); },
         .shader = unshadowedShader,
         .specialize = {}});
}

}  // namespace ls
