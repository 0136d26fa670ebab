#include "screen_lin_node.h"
#include "shared_nodes.h"
#include "unshadowed_directional_frag.h"
#include "unshadowed_table_frag.h"

namespace ls {

rg::ImageRef addUnshadowed(rg::RenderGraph& graph, const UnshadowedInputs& in) {
    return addScreenLinNode(graph, in.frame.shared,
                            {.name = "unshadowed in-scattering",
                             .constants = in.frame.constants,
                             .depth = in.frame.depth,
                             // The table; an unshadowed frame has nothing else.
                             .rows =
                                 [in](rg::BindingTable& table) {
                                     addMarchInputs(table, in.frame.shared, in.light);
                                 },
                             .shader =
                                 [](const ScatterSpec& spec) {
                                     return spec.light != LightKind::Directional
                                                ? rg::spirv(ls_spirv::unshadowed_table_frag)
                                                : rg::spirv(ls_spirv::unshadowed_directional_frag);
                                 },
                             .specialize = {}});
}

}  // namespace ls
