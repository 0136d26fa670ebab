#pragma once
// Small helpers the node builders share: descriptor sets that start with the frame constants,
// full-screen pipelines, workgroup counts, and the light's images. Each node picks its own shader
// variant (shaders/CMakeLists.txt): the light's kind and options choose among the variants a
// method's shader is built in.
#include <string>
#include <vector>

#include "node_inputs.h"
#include "rendergraph/pass_context.h"
#include "rendergraph/pipeline.h"
#include "rendergraph/render_graph.h"

namespace ls {

inline uint32_t groupCount(uint32_t n, uint32_t size) { return (n + size - 1) / size; }

// A push set whose binding 0 is the frame-constants uniform buffer.
rg::DescriptorPush frameSet(const rg::PassContext& ctx, rg::BufferRef constants);

rg::Binding sampledBinding(uint32_t binding);
rg::Binding storageBinding(uint32_t binding);
rg::Binding uniformBinding(uint32_t binding);
rg::Binding storageBufferBinding(uint32_t binding);

// A full-screen triangle pipeline for the pass's render targets.
rg::GraphicsPipelineDesc fullscreenPipeline(rg::ShaderCode fragment, const rg::PassContext& ctx,
                                            std::vector<rg::Binding> bindings);

// Key for a pipeline: its name, its specialisation and the pass's target formats.
std::string pipelineKey(const std::string& name, const rg::PassContext& ctx,
                        const std::string& variant = {});

}  // namespace ls

namespace ls {

// The inputs every marching node samples besides its own textures: the shadow map (binding 6), the
// point-light table (7) and the light-color texture (8), each only when the frame has it.
void declareMarchInputs(rg::PassBuilder& pass, const NodeInputs& in);
void appendMarchBindings(std::vector<rg::Binding>& bindings, const NodeInputs& in);
void pushMarchInputs(rg::DescriptorPush& set, const rg::PassContext& ctx, const NodeInputs& in);

}  // namespace ls
