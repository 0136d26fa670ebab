#pragma once
// Vulkan's rules for the layouts an image may be in where its owner hands it to a graph and takes
// it back: which layouts an image of a given format and usage may start a frame in and be left in.
// One table (layout_rules.cpp) for the runtime's checks of its imports and the plugin's of the
// engine's images, so that the two cannot disagree; each words its own refusals.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace rg {

// "SHADER_READ_ONLY_OPTIMAL" style name (the VK_IMAGE_LAYOUT_ prefix dropped), or nullptr for a
// layout the table does not hold.
const char* layoutName(VkImageLayout layout);
// "SAMPLED" style name of one usage flag (the VK_IMAGE_USAGE_ prefix and _BIT dropped), or nullptr
// for a flag the table does not hold.
const char* usageName(VkImageUsageFlagBits usage);

enum class LayoutEnd : uint8_t {
    Initial,  // the layout the image is in when the frame starts
    Final,    // the layout it must be left in
};

enum class LayoutFault : uint8_t {
    None,
    Unknown,        // a layout the table does not hold
    NoFinalLayout,  // UNDEFINED as the final layout: the owner did not say where the image goes
    NotFinal,       // PREINITIALIZED as the final layout: an image can only start in it
    Discards,       // UNDEFINED as the initial layout of an image whose contents are read
    HostColorOnly,  // PREINITIALIZED, and the format is depth/stencil
    ColorOnly,      // COLOR_ATTACHMENT_OPTIMAL, and the format is depth/stencil
    SwapchainOnly,  // PRESENT_SRC_KHR (a swapchain's color images), and the format is depth/stencil
    DepthOnly,      // a layout of the depth aspect, and the format has no depth
    StencilAlone,   // a layout of the stencil aspect alone
    MissingUsage,   // the image was created with none of the usages the layout needs
};

struct LayoutVerdict {
    LayoutFault fault = LayoutFault::None;
    // MissingUsage: the usages of which the image needs one, "SAMPLED or INPUT_ATTACHMENT".
    std::string neededUsage;
};

// Whether an image of `format`, created with `usage`, may be in `layout` at that end of the frame.
// `contentsRead`: what the image holds when the frame starts is read.
LayoutVerdict layoutVerdict(VkImageLayout layout, VkFormat format, VkImageUsageFlags usage,
                            LayoutEnd end, bool contentsRead);

}  // namespace rg
