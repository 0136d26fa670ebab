#pragma once
// The result of compiling a RenderGraph: plain data, no Vulkan objects, so it can be inspected and
// tested without a device and realised later by the executor.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "device_caps.h"
#include "pass_decl.h"
#include "resources.h"

namespace rg {

struct BarrierPlan {
    uint32_t resource = kInvalidIndex;
    bool buffer = false;
    VkPipelineStageFlags2 srcStages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 srcAccess = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 dstStages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 dstAccess = VK_ACCESS_2_NONE;
    VkImageLayout oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout newLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    bool firstUse = false;  // contents discarded (transient's first use in the frame)
    bool aliased = false;   // the memory was used by another resource before
};

struct AttachmentPlan {
    uint32_t resource = kInvalidIndex;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkAttachmentLoadOp load = VK_ATTACHMENT_LOAD_OP_LOAD;
    VkAttachmentStoreOp store = VK_ATTACHMENT_STORE_OP_STORE;
    VkClearValue clear{};
};

// How one pass touches one resource, all its declared uses combined.
struct PassResourceState {
    uint32_t resource = kInvalidIndex;
    bool buffer = false;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 stages = 0;
    VkAccessFlags2 access = 0;
    bool writes = false;
};

struct PassPlan {
    uint32_t pass = kInvalidIndex;      // index into RenderGraph::passes()
    std::vector<BarrierPlan> barriers;  // recorded as one vkCmdPipelineBarrier2 before the pass
    std::vector<PassResourceState> states;
    std::vector<AttachmentPlan> colors;
    std::optional<AttachmentPlan> depth;
    std::optional<AttachmentPlan> stencil;
    VkExtent2D renderExtent{0, 0};
    // It renders over the whole screen (its extent is the graph's screen): a frame recorded at a
    // smaller screen (GraphExecutor::record's `screen`) renders over that instead.
    bool screenSized = false;
};

struct ResourcePlan {
    bool used = false;  // by a pass that survived culling
    bool buffer = false;
    bool imported = false;
    VkExtent2D extent{0, 0};
    VkImageUsageFlags imageUsage = 0;
    VkBufferUsageFlags bufferUsage = 0;
    MemoryRequirements memory;
    uint32_t memoryType = 0;
    uint32_t firstPass = kInvalidIndex;  // positions in CompiledGraph::passes
    uint32_t lastPass = kInvalidIndex;
    uint32_t block = kInvalidIndex;  // transient only
    VkDeviceSize offset = 0;
    VkImageLayout lastLayout = VK_IMAGE_LAYOUT_UNDEFINED;
};

struct MemoryBlockPlan {
    uint32_t memoryType = 0;
    VkDeviceSize size = 0;
};

struct CompiledGraph {
    std::vector<PassPlan> passes;         // execution order
    std::vector<uint32_t> culled;         // declaration indices of passes nobody needs
    std::vector<ResourcePlan> resources;  // indexed like RenderGraph::resources()
    std::vector<MemoryBlockPlan> blocks;
    std::vector<BarrierPlan> finalBarriers;  // imports handed back in their final states
    VkDeviceSize unaliasedBytes = 0;         // every used transient in memory of its own
    VkDeviceSize aliasedBytes = 0;           // the blocks actually allocated
    VkExtent2D screen{0, 0};
    bool exactSizes = false;        // memory sizes from a device rather than an estimate
    bool poisonTransients = false;  // see CompileOptions
};

struct CompileOptions {
    bool aliasing = true;
    // Debugging: every transient is filled with a signalling pattern (NaN in float formats, all
    // ones in integer formats) at its first use in each frame, before its first pass. A pass that
    // reads what it never wrote then reads NaN instead of whatever an aliased resource left behind,
    // so a clean output proves no pass depends on stale memory. Adds TRANSFER_DST usage.
    bool poisonTransients = false;
};

}  // namespace rg
