#include "analytic_node.h"

#include "analytic_frag.h"
#include "shared/screen_lin_node.h"

namespace ls {

rg::ImageRef addAnalytic(rg::RenderGraph& graph, const AnalyticInputs& in) {
    return addScreenLinNode(
        graph, in.chain.shared, in.chain.spec,
        {.name = "analytic in-scattering (seed 001)",
         .constants = in.chain.constants,
         .depth = in.chain.depth,
         .values = in.chain.values,
         .rows = {},
         .shader = [](const ScatterSpec&) { return rg::spirv(ls_spirv::analytic_frag); },
         .specialize = {}});
}

}  // namespace ls
