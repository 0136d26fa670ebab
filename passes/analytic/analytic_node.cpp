#include "analytic_node.h"

#include "analytic_frag.h"
#include "shared/screen_lin_node.h"

namespace ls {

rg::ImageRef addAnalytic(rg::RenderGraph& graph, const AnalyticInputs& in) {
    return addScreenLinNode(
        graph, in.frame.shared, in.frame.spec,
        {.name = "analytic in-scattering (seed 001)",
         .constants = in.frame.constants,
         .depth = in.frame.depth,
         .values = in.frame.values,
         .rows = {},
         .shader = [](const ScatterSpec&) { return rg::spirv(ls_spirv::analytic_frag); },
         .specialize = {}});
}

}  // namespace ls
