#pragma once
// Small helpers the node builders share: binding tables that start with the frame constants,
// full-screen pipelines, workgroup counts, and the light's images. Each node picks its own shader
// variant (shaders/CMakeLists.txt): the light's kind and options choose among the variants a
// method's shader is built in. Binding numbers are shaders/shared/bindings.h's, and a method's own
// shaders/<method>/<method>_bindings.h's.
#include <vector>

#include "chain_context.h"
#include "rendergraph/binding_table.h"
#include "rendergraph/pass_context.h"
#include "rendergraph/pipeline.h"
#include "rendergraph/render_graph.h"
#include "shaders/shared/bindings.h"

namespace ls {

inline uint32_t groupCount(uint32_t n, uint32_t size) {
    return (n + size - 1) / size;
}

// A binding table whose first row is the frame-constants uniform buffer (LS_BINDING_FRAME).
rg::BindingTable frameTable(rg::PassBuilder& pass, rg::BufferRef constants,
                            VkPipelineStageFlags2 stages = 0);

// Limits the pass's draws to the light's screen rectangle this frame (LightFrame::screenRect), so
// that a per-pixel pass over a small light costs its pixels; false when the rectangle is empty and
// nothing is to be drawn. The pass's target is cleared, so the rest of it holds 0.
bool scissorToLight(rg::PassContext& ctx, rg::HostDataRef<LightFrame> values);

// A full-screen triangle pipeline for the pass's render targets.
rg::GraphicsPipelineDesc fullscreenPipeline(rg::ShaderCode fragment, const rg::PassContext& ctx,
                                            std::vector<rg::Binding> bindings);

}  // namespace ls

namespace ls {

// The inputs every marching node samples besides its own textures: the shadow map, the
// point-light table and the light-color texture, each only when the frame has it.
void addMarchInputs(rg::BindingTable& table, const Shared& shared, const LightImages& light);

}  // namespace ls
