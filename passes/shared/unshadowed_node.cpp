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

rg::ImageRef addUnshadowed(rg::RenderGraph& graph, const UnshadowedInputs& in) {
    return addScreenLinNode(
        graph, in.frame.shared, in.frame.spec,
        {.name = "unshadowed in-scattering",
         .constants = in.frame.constants,
         .depth = in.frame.depth,
         .values = in.frame.values,
         // The table; an unshadowed frame has nothing else.
         .rows =
             [in](rg::BindingTable& table) { addMarchInputs(table, in.frame.shared, in.light); },
         .shader = unshadowedShader,
         .specialize = {}});
}

}  // namespace ls
