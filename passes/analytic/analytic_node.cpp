#include "analytic_node.h"

#include "analytic_frag.h"
#include "shared/screen_lin_node.h"

namespace ls {

rg::ImageRef addAnalytic(rg::RenderGraph& graph, const Shared& shared, const AnalyticInputs& in) {
    return addScreenLinNode(
        graph, shared,
        {.name = "analytic in-scattering (seed 001)",
         .constants = in.constants,
         .depth = in.depth,
         .rows = {},
         .shader = [](const ScatterSpec&) { return rg::spirv(ls_spirv::analytic_frag); },
         .specialize = {}});
}

}  // namespace ls
