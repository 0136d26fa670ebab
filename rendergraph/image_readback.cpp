#include "image_readback.h"

namespace rg {

void recordReadback(const Device& device, VkCommandBuffer cmd, VkImage image, VkImageLayout layout,
                    VkExtent2D extent, VkBuffer buffer, VkImageAspectFlags aspect, uint32_t layers,
                    uint32_t depth) {
    VkBufferImageCopy region{};
    region.imageSubresource = {aspect, 0, 0, layers};
    region.imageExtent = {extent.width, extent.height, depth};
    device.vk().CmdCopyImageToBuffer(cmd, image, layout, buffer, 1, &region);
    VkMemoryBarrier2 toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    toHost.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &toHost;
    device.vk().CmdPipelineBarrier2(cmd, &dep);
}

}  // namespace rg
