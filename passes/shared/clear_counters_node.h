#pragma once
// DebugOptions::countSteps: the frame's one counter buffer, which the counting chains add into
// (MethodUnit::stepCountBytes), zeroed before the first of them.
#include "rendergraph/render_graph.h"

namespace ls {

struct ClearCountersInputs {
    rg::BufferRef counts;
};
// Returns the cleared counter's new version.
rg::BufferRef addClearCounters(rg::RenderGraph& g, const ClearCountersInputs& in);

}  // namespace ls
