#include "cone_march_node.h"

#include "cone_march_frag_variants.h"
#include "cone_march_shader.h"
#include "shaders/cone_march/cone_march_bindings.h"
#include "shared/screen_lin_node.h"
#include "shared/shader_variant.h"

namespace ls {

// Bindings that only some frames have are build-time variants, so a pipeline never declares a
// descriptor it is not given.
// A point light's cube map (`cube`, with a shadow map) comes without light color (refused with it).
rg::ShaderCode coneMarchShader(bool shadowMap, bool lightColor, bool cube) {
    return pickShader(ls_spirv::cone_march_frag_variants,
                      {{"LS_SHADOW_MAP", shadowMap},
                       {"LS_CUBE_SHADOW", shadowMap && cube},
                       {"LS_LIGHT_COLOR", lightColor && !(shadowMap && cube)}});
}

rg::ImageRef addConeMarch(rg::RenderGraph& graph, const ConeMarchInputs& in,
                          const ConeMarchOptions& options) {
    const bool shadow = in.light.shadowMap.valid(), color = in.light.lightColor.valid();
    const Shared& shared = in.chain.shared;
    return addScreenLinNode(graph, shared, in.chain.spec,
                            {.name = options.coneLimited ? "cone-limited ray march (seed 003)"
                                                         : "naive ray march (seed 003's baseline)",
                             .constants = in.chain.constants,
                             .depth = in.chain.depth,
                             .values = in.chain.values,
                             .rows =
                                 [light = in.light, shared](rg::BindingTable& table) {
                                     const auto& s = samplersOf(shared);
                                     table
                                         .sampledIfValid(LS_BINDING_SHADOW_MAP, light.shadowMap,
                                                         s.nearest(), VK_IMAGE_ASPECT_DEPTH_BIT)
                                         .sampledIfValid(LS_BINDING_LIGHT_COLOR, light.lightColor,
                                                         s.linear());
                                 },
                             .shader =
                                 [shadow, color](const ScatterSpec& spec) {
                                     return coneMarchShader(shadow, color, spec.cubeShadow);
                                 },
                             .specialize =
                                 [options](rg::Specialization& s) {
                                     s.set(LS_SPEC_CONE_SAMPLES, options.samples)
                                         .set(LS_SPEC_CONE_LIMITED, options.coneLimited)
                                         .set(LS_SPEC_CONE_JITTER, options.jitter);
                                 }});
}

}  // namespace ls
