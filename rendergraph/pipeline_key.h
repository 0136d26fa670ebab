#pragma once
// A pipeline's whole description as one comparable value, so that a cache of pipelines keyed by it
// can never hand out a pipeline built from a description that differs in any field. The shader
// code is identified by its words' address and size (embedded SPIR-V arrays live as long as the
// program); every other field goes in by value.
#include <cstdint>
#include <vector>

#include "pipeline.h"

namespace rg {

using PipelineKey = std::vector<uint64_t>;

PipelineKey pipelineKey(const GraphicsPipelineDesc& desc);
PipelineKey pipelineKey(ShaderCode code, const std::vector<Binding>& bindings,
                        uint32_t pushConstantBytes, const Specialization& specialization);

}  // namespace rg
