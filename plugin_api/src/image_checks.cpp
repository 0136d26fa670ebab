#include "image_checks.h"

#include "field_checks.h"
#include "rendergraph/format_info.h"
#include "rendergraph/layout_rules.h"

namespace lightscatter::detail {
namespace {

// The table's faults in the plugin's words, after "the layout": the runtime words its own.
std::string faultText(const rg::LayoutVerdict& v) {
    switch (v.fault) {
        case rg::LayoutFault::None:
            return {};
        case rg::LayoutFault::Unknown:
            return "is not a layout the plugin takes";
        case rg::LayoutFault::NoFinalLayout:
        case rg::LayoutFault::NotFinal:
            return "is not a layout an image can be left in";
        case rg::LayoutFault::Discards:
            return "discards what the image holds, and the plugin reads it";
        case rg::LayoutFault::HostColorOnly:
            return "is for linear color images written by the host";
        case rg::LayoutFault::ColorOnly:
            return "is a color layout, and the format is depth/stencil";
        case rg::LayoutFault::SwapchainOnly:
            return "is a swapchain layout, and the format is depth/stencil";
        case rg::LayoutFault::DepthOnly:
            return "is a depth layout, and the format has no depth";
        case rg::LayoutFault::StencilAlone:
            return "is a layout of the stencil aspect alone, and the plugin uses color or depth";
        case rg::LayoutFault::MissingUsage:
            return "needs an image created with " + v.neededUsage + " usage";
    }
    return {};
}

void checkLayout(const rg::LayoutVerdict& v, VkImageLayout layout, const ImageInput& img,
                 const std::string& field) {
    if (v.fault == rg::LayoutFault::None) return;
    const char* name = rg::layoutName(layout);
    fail(field + " " +
         (name ? std::string(name) : "#" + std::to_string(static_cast<int64_t>(layout))) +
         " cannot hold this " + rg::formatName(img.format) + " image: the layout " + faultText(v));
}

}  // namespace

void checkImage(const ImageInput& img, const std::string& field, VkImageUsageFlagBits usage,
                bool read, bool volume) {
    if (!img.image) fail(field + ".image is VK_NULL_HANDLE");
    if (img.extent.width == 0 || img.extent.height == 0 || (volume && img.depth == 0))
        fail(field + ".extent is " + std::to_string(img.extent.width) + "x" +
             std::to_string(img.extent.height) +
             (volume ? "x" + std::to_string(img.depth) : std::string()) + ": must not be empty");
    if (!volume && img.depth != 1)
        fail(field + ".depth = " + std::to_string(img.depth) +
             ": must be 1 (a 2D image; only volumeOut is a 3D one)");
    if ((img.usage & usage) == 0)
        fail(field + ".usage lacks " + rg::usageName(usage) +
             ", which the plugin needs to read or write it");
    const rg::LayoutVerdict atStart =
        rg::layoutVerdict(img.layout, img.format, img.usage, rg::LayoutEnd::Initial, read);
    const rg::LayoutVerdict atEnd =
        rg::layoutVerdict(img.finalLayout, img.format, img.usage, rg::LayoutEnd::Final, read);
    // Named first, whatever the initial layout: an omission of the engine's, not a layout's fault.
    if (atEnd.fault == rg::LayoutFault::NoFinalLayout)
        fail(field + ".finalLayout is UNDEFINED: say which layout the image must be left in");
    checkLayout(atStart, img.layout, img, field + ".layout");
    checkLayout(atEnd, img.finalLayout, img, field + ".finalLayout");
}

void checkDepthFormat(VkFormat f, const std::string& field) {
    if (!rg::hasDepth(f))
        fail(field + ".format " + rg::formatName(f) +
             " is not a depth format (D16_UNORM, X8_D24_UNORM_PACK32, D32_SFLOAT, or one of these "
             "with stencil)");
}

void oneLayer(const ImageInput* img, const std::string& field) {
    if (img && img->arrayLayers != 1)
        fail(field + ".arrayLayers = " + std::to_string(img->arrayLayers) +
             ": must be 1 (only a point light's shadow map has layers: 6)");
}

}  // namespace lightscatter::detail
