#include "layout_rules.h"

#include <array>
#include <string_view>

#include "format_info.h"

namespace rg {
namespace {

// Which formats' images a layout is for.
enum class Formats : uint8_t {
    Any,
    Color,  // neither depth nor stencil
    Depth,  // with a depth aspect
    None,   // the stencil aspect's own layouts: what is handed over is a color or a depth image
};

// The usages of which an image needs one to be in a layout, in the order a message names them, up
// to the first 0; none: any usage will do.
using Usages = std::array<VkImageUsageFlagBits, 3>;
constexpr Usages kAnyUsage{};
constexpr Usages kColorAttachment{VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT};
constexpr Usages kDepthAttachment{VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT};
constexpr Usages kShaderRead{VK_IMAGE_USAGE_SAMPLED_BIT, VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT};
constexpr Usages kAnyRead{VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_USAGE_SAMPLED_BIT,
                          VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT};

struct LayoutRule {
    VkImageLayout layout;
    std::string_view name;
    LayoutFault asFinal;  // why an image cannot be left in it; None: it can
    bool discards;        // as the initial layout: what the image holds is undefined
    Formats formats;
    LayoutFault otherFormat;     // the fault for an image of a format `formats` excludes
    Usages color, depthStencil;  // by the image's format
};

constexpr LayoutRule rule(VkImageLayout layout, std::string_view name, Formats formats,
                          LayoutFault otherFormat, Usages color, Usages depthStencil) {
    return {layout, name, LayoutFault::None, false, formats, otherFormat, color, depthStencil};
}
constexpr LayoutRule anyFormat(VkImageLayout layout, std::string_view name, Usages usages) {
    return rule(layout, name, Formats::Any, LayoutFault::None, usages, usages);
}
constexpr LayoutRule depthLayout(VkImageLayout layout, std::string_view name, Usages usages) {
    return rule(layout, name, Formats::Depth, LayoutFault::DepthOnly, kAnyUsage, usages);
}

constexpr std::array kLayouts = {
    LayoutRule{VK_IMAGE_LAYOUT_UNDEFINED, "UNDEFINED", LayoutFault::NoFinalLayout, true,
               Formats::Any, LayoutFault::None, kAnyUsage, kAnyUsage},
    anyFormat(VK_IMAGE_LAYOUT_GENERAL, "GENERAL", kAnyUsage),
    rule(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, "COLOR_ATTACHMENT_OPTIMAL", Formats::Color,
         LayoutFault::ColorOnly, kColorAttachment, kAnyUsage),
    depthLayout(VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                "DEPTH_STENCIL_ATTACHMENT_OPTIMAL", kDepthAttachment),
    depthLayout(VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, "DEPTH_STENCIL_READ_ONLY_OPTIMAL",
                kDepthAttachment),
    anyFormat(VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "SHADER_READ_ONLY_OPTIMAL", kShaderRead),
    anyFormat(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, "TRANSFER_SRC_OPTIMAL",
              {VK_IMAGE_USAGE_TRANSFER_SRC_BIT}),
    anyFormat(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, "TRANSFER_DST_OPTIMAL",
              {VK_IMAGE_USAGE_TRANSFER_DST_BIT}),
    // Linear color images the host wrote before any layout transition.
    LayoutRule{VK_IMAGE_LAYOUT_PREINITIALIZED, "PREINITIALIZED", LayoutFault::NotFinal, false,
               Formats::Color, LayoutFault::HostColorOnly, kAnyUsage, kAnyUsage},
    depthLayout(VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL,
                "DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL", kDepthAttachment),
    depthLayout(VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL,
                "DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL", kDepthAttachment),
    depthLayout(VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, "DEPTH_ATTACHMENT_OPTIMAL",
                kDepthAttachment),
    depthLayout(VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, "DEPTH_READ_ONLY_OPTIMAL", kAnyRead),
    rule(VK_IMAGE_LAYOUT_STENCIL_ATTACHMENT_OPTIMAL, "STENCIL_ATTACHMENT_OPTIMAL", Formats::None,
         LayoutFault::StencilAlone, kAnyUsage, kAnyUsage),
    rule(VK_IMAGE_LAYOUT_STENCIL_READ_ONLY_OPTIMAL, "STENCIL_READ_ONLY_OPTIMAL", Formats::None,
         LayoutFault::StencilAlone, kAnyUsage, kAnyUsage),
    anyFormat(VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, "READ_ONLY_OPTIMAL", kAnyRead),
    rule(VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, "ATTACHMENT_OPTIMAL", Formats::Any, LayoutFault::None,
         kColorAttachment, kDepthAttachment),
    rule(VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, "PRESENT_SRC_KHR", Formats::Color,
         LayoutFault::SwapchainOnly, kAnyUsage, kAnyUsage),
};

struct UsageName {
    VkImageUsageFlagBits usage;
    std::string_view name;
};

constexpr std::array kUsages = {
    UsageName{VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "TRANSFER_SRC"},
    UsageName{VK_IMAGE_USAGE_TRANSFER_DST_BIT, "TRANSFER_DST"},
    UsageName{VK_IMAGE_USAGE_SAMPLED_BIT, "SAMPLED"},
    UsageName{VK_IMAGE_USAGE_STORAGE_BIT, "STORAGE"},
    UsageName{VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, "COLOR_ATTACHMENT"},
    UsageName{VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "DEPTH_STENCIL_ATTACHMENT"},
    UsageName{VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT, "INPUT_ATTACHMENT"},
};

const LayoutRule* find(VkImageLayout layout) {
    for (const auto& r : kLayouts)
        if (r.layout == layout) return &r;
    return nullptr;
}

bool takes(Formats formats, VkFormat format) {
    switch (formats) {
        case Formats::Any:
            return true;
        case Formats::Color:
            return !isDepthStencil(format);
        case Formats::Depth:
            return hasDepth(format);
        case Formats::None:
            return false;
    }
    return false;
}

// "A", "A or B", "A, B or C".
std::string usageList(const Usages& usages) {
    std::string list;
    for (size_t i = 0; i < usages.size() && usages[i]; ++i) {
        const bool last = i + 1 == usages.size() || !usages[i + 1];
        if (i > 0) list += last ? " or " : ", ";
        list += usageName(usages[i]);
    }
    return list;
}

}  // namespace

const char* layoutName(VkImageLayout layout) {
    const LayoutRule* r = find(layout);
    return r ? r->name.data() : nullptr;
}

const char* usageName(VkImageUsageFlagBits usage) {
    for (const auto& u : kUsages)
        if (u.usage == usage) return u.name.data();
    return nullptr;
}

LayoutVerdict layoutVerdict(VkImageLayout layout, VkFormat format, VkImageUsageFlags usage,
                            LayoutEnd end, bool contentsRead) {
    const LayoutRule* r = find(layout);
    if (!r) return {LayoutFault::Unknown, {}};
    if (end == LayoutEnd::Final && r->asFinal != LayoutFault::None) return {r->asFinal, {}};
    if (end == LayoutEnd::Initial && r->discards && contentsRead)
        return {LayoutFault::Discards, {}};
    if (!takes(r->formats, format)) return {r->otherFormat, {}};
    const Usages& needed = isDepthStencil(format) ? r->depthStencil : r->color;
    VkImageUsageFlags any = 0;
    for (VkImageUsageFlagBits u : needed) any |= u;
    if (any == 0 || (usage & any) != 0) return {};
    return {LayoutFault::MissingUsage, usageList(needed)};
}

}  // namespace rg
