#pragma once
// Reports of a compiled graph: per pass (order, time), per resource (format, extent, bytes,
// lifetime, memory placement), totals; as a readable table, JSON, or Graphviz DOT.
#include <nlohmann/json.hpp>
#include <string>

#include "compiled_graph.h"
#include "executor.h"
#include "render_graph.h"

namespace rg {

nlohmann::json reportJson(const RenderGraph& graph, const CompiledGraph& compiled,
                          const FrameTimings* timings = nullptr);
std::string reportText(const RenderGraph& graph, const CompiledGraph& compiled,
                       const FrameTimings* timings = nullptr);
std::string reportDot(const RenderGraph& graph, const CompiledGraph& compiled);

std::string formatBytes(VkDeviceSize bytes);  // "12.5 MiB"

}  // namespace rg
