#pragma once
// The read-back of an image outside a graph, as engines and tests do it after a frame: a copy into
// a host-visible buffer and the barrier that makes it visible to the host.
#include <vulkan/vulkan.h>

#include "device.h"

namespace rg {

// Records the copy of mip 0, layers 0 .. `layers` - 1 of `aspect`, of `image` (in `layout`, which
// allows transfer reads; a 3D image of `depth` slices has one layer) into `buffer` from offset 0,
// tightly packed, and then the barrier that makes the copy visible to host reads: once the command
// buffer's submission has finished, the host reads the texels.
void recordReadback(const Device& device, VkCommandBuffer cmd, VkImage image, VkImageLayout layout,
                    VkExtent2D extent, VkBuffer buffer,
                    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT, uint32_t layers = 1,
                    uint32_t depth = 1);

}  // namespace rg
