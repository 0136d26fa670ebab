#pragma once
// What a pass's execute callback receives: its command buffer (inside dynamic rendering for
// graphics passes, with viewport and scissor set), and the Vulkan objects behind its handles.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "device.h"
#include "host_data.h"
#include "persistent_store.h"
#include "resources.h"

namespace rg {

class GraphExecutor;
struct PassResourceState;

struct RenderingFormats {
    std::vector<VkFormat> colors;
    VkFormat depth = VK_FORMAT_UNDEFINED;
    VkFormat stencil = VK_FORMAT_UNDEFINED;
};

class PassContext {
  public:
    PassContext(GraphExecutor& executor, uint32_t position, VkCommandBuffer cmd)
        : executor_(executor), position_(position), cmd_(cmd) {}

    VkCommandBuffer cmd() const { return cmd_; }
    const Device& device() const;
    // The entry points a pass records with (the device's).
    const VulkanFunctions& vk() const { return device().vk(); }
    const std::string& passName() const;

    VkImage image(ImageRef ref) const;
    // Color images: the whole image. Depth-stencil images: both aspects (attachments); pass
    // VK_IMAGE_ASPECT_DEPTH_BIT or _STENCIL_BIT for a view that samples one aspect. view() and
    // layout() throw VulkanError for an image the pass did not declare: its barriers were derived
    // from the declarations, so the image may be in any layout, or still being written.
    VkImageView view(ImageRef ref, VkImageAspectFlags aspect = 0) const;
    VkImageLayout layout(ImageRef ref) const;  // the layout the image is in during this pass
    VkExtent2D extent(ImageRef ref) const;
    VkFormat format(ImageRef ref) const;
    VkBuffer buffer(BufferRef ref) const;
    VkDeviceSize size(BufferRef ref) const;

    // This frame's value of host data the graph declared (RenderGraph::hostData); throws
    // VulkanError naming the pass and the data when the frame did not give it.
    template <typename T>
    const T& data(HostDataRef<T> ref) const {
        return *static_cast<const T*>(hostData(ref.graph, ref.id, detail::hostDataTag<T>()));
    }

    // A persistent image's state as the frames recorded before this one left it
    // (RenderGraph::persistentImage), and what this frame leaves in it: a pass that fills the image
    // says so, with what it filled it from (a stamp the next frames compare).
    PersistentState persistent(ImageRef ref) const;
    void wrote(ImageRef ref, uint64_t stamp);
    // Whether a history's previous image holds the frame just before's, and for how many frames
    // (RenderGraph::historyImages; either of its two images).
    HistoryState history(ImageRef ref) const;

    VkExtent2D renderExtent() const;                   // graphics passes
    const RenderingFormats& renderingFormats() const;  // for pipeline creation

  private:
    const void* hostData(uint32_t graph, uint32_t id, const void* tag) const;
    const PassResourceState& declared(ImageRef ref, const char* asking) const;

    GraphExecutor& executor_;
    uint32_t position_;
    VkCommandBuffer cmd_;
};

}  // namespace rg
