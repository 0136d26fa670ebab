#pragma once
// Facts about VkFormat values that the runtime needs without a device: aspects, texel size and a
// readable name for messages and reports.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace rg {

bool hasDepth(VkFormat format);
bool hasStencil(VkFormat format);
inline bool isDepthStencil(VkFormat f) {
    return hasDepth(f) || hasStencil(f);
}
VkImageAspectFlags fullAspect(VkFormat format);
// UINT and SINT color formats (cleared and read as integers).
bool isIntegerFormat(VkFormat format);

// Bytes per texel for the uncompressed formats the project uses; 0 for unknown formats. For packed
// depth-stencil formats this is the size an implementation typically stores (D24S8: 4, D32S8: 8).
uint32_t texelBytes(VkFormat format);

// "R16G16_SFLOAT" style name (the VK_FORMAT_ prefix dropped), or "format #N" when unknown.
std::string formatName(VkFormat format);

}  // namespace rg
