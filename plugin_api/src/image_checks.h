#pragma once
// The engine's images: a handle, an extent, the usage the plugin needs, and layouts Vulkan lets an
// image of that format and usage be in when the frame starts and when it ends
// (rendergraph/layout_rules.h, the table the runtime's checks of its imports share).
#include <vulkan/vulkan.h>

#include <string>

#include <lightscatter/lightscatter.h>

namespace lightscatter::detail {

// `usage`: the one the plugin reads or writes the image with. `read`: the plugin reads what the
// image holds when the frame starts. `volume`: a 3D image (volumeOut); the others are 2D, depth 1.
void checkImage(const ImageInput& img, const std::string& field, VkImageUsageFlagBits usage,
                bool read = true, bool volume = false);
void checkDepthFormat(VkFormat f, const std::string& field);
// One array layer: `img` may be null (an image the frame does not give).
void oneLayer(const ImageInput* img, const std::string& field);

}  // namespace lightscatter::detail
