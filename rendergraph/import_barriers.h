#pragma once
// Where an imported resource stands before a graph and where it must be left after it, read from
// its description in one place: the compiler plans an import's first barrier and its hand-back with
// these, and the executor sets them again on every frame it records, since an engine may change an
// import's stages and access from one frame to the next without compiling again.
#include <vulkan/vulkan.h>

#include "compiled_graph.h"
#include "render_graph.h"

namespace rg::detail {

struct ImportEnd {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // UNDEFINED for a buffer
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
};

ImportEnd importStart(const ResourceDecl& r);   // its initial layout, stages and access
ImportEnd importFinish(const ResourceDecl& r);  // its final ones

// The barrier waits on the import's start: source stages, access and old layout.
void waitOnImport(BarrierPlan& b, const ResourceDecl& r);
// The barrier leaves the import at its finish: destination stages, access and new layout.
void handBackImport(BarrierPlan& b, const ResourceDecl& r);

}  // namespace rg::detail
