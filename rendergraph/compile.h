#pragma once
// Compilation: validate, cull, order, compute lifetimes, place transient memory, derive barriers.
// Every rejection is a GraphError naming the pass, the resource and the rule.
#include <string>

#include "compiled_graph.h"
#include "device_caps.h"
#include "graph_error.h"
#include "render_graph.h"

namespace rg {

CompiledGraph compile(const RenderGraph& graph, const DeviceCaps& caps,
                      const CompileOptions& options = {});

// How a transient image of this plan is created (the executor creates exactly this).
VkImageCreateInfo transientImageInfo(const ResourceDecl& r, const ResourcePlan& plan);

// The stages of the compiler, exposed for tests.
namespace detail {

void validate(const RenderGraph& graph, const DeviceCaps& caps);

struct Schedule {
    std::vector<uint32_t> order;  // live passes, declaration indices, execution order
    std::vector<uint32_t> culled;
};
Schedule schedule(const RenderGraph& graph);

// Derives the combined state of each resource in each pass and the barriers between passes.
void deriveSync(const RenderGraph& graph, CompiledGraph& out);

// A pass's or resource's name as the compiler's messages quote it.
inline std::string quote(const std::string& s) {
    return "'" + s + "'";
}

}  // namespace detail
}  // namespace rg
