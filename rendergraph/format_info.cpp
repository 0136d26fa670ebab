#include "format_info.h"

#include <array>
#include <string_view>

namespace rg {
namespace {

struct FormatFacts {
    VkFormat format;
    std::string_view name;
    uint32_t bytes;
    bool depth;
    bool stencil;
};

constexpr std::array kFormats = {
    FormatFacts{VK_FORMAT_R8_UNORM, "R8_UNORM", 1, false, false},
    FormatFacts{VK_FORMAT_R8G8_UNORM, "R8G8_UNORM", 2, false, false},
    FormatFacts{VK_FORMAT_R8G8B8A8_UNORM, "R8G8B8A8_UNORM", 4, false, false},
    FormatFacts{VK_FORMAT_R8G8B8A8_SRGB, "R8G8B8A8_SRGB", 4, false, false},
    FormatFacts{VK_FORMAT_B8G8R8A8_UNORM, "B8G8R8A8_UNORM", 4, false, false},
    FormatFacts{VK_FORMAT_B8G8R8A8_SRGB, "B8G8R8A8_SRGB", 4, false, false},
    FormatFacts{VK_FORMAT_R8G8B8A8_UINT, "R8G8B8A8_UINT", 4, false, false},
    FormatFacts{VK_FORMAT_A2B10G10R10_UNORM_PACK32, "A2B10G10R10_UNORM_PACK32", 4, false, false},
    FormatFacts{VK_FORMAT_A2R10G10B10_UNORM_PACK32, "A2R10G10B10_UNORM_PACK32", 4, false, false},
    FormatFacts{VK_FORMAT_R16G16B16A16_UNORM, "R16G16B16A16_UNORM", 8, false, false},
    FormatFacts{VK_FORMAT_R16_SFLOAT, "R16_SFLOAT", 2, false, false},
    FormatFacts{VK_FORMAT_R16_UINT, "R16_UINT", 2, false, false},
    FormatFacts{VK_FORMAT_R16G16_SFLOAT, "R16G16_SFLOAT", 4, false, false},
    FormatFacts{VK_FORMAT_R16G16_UINT, "R16G16_UINT", 4, false, false},
    FormatFacts{VK_FORMAT_R16G16_UNORM, "R16G16_UNORM", 4, false, false},
    FormatFacts{VK_FORMAT_R16G16B16A16_SFLOAT, "R16G16B16A16_SFLOAT", 8, false, false},
    FormatFacts{VK_FORMAT_R32_SFLOAT, "R32_SFLOAT", 4, false, false},
    FormatFacts{VK_FORMAT_R32_UINT, "R32_UINT", 4, false, false},
    FormatFacts{VK_FORMAT_R32G32_SFLOAT, "R32G32_SFLOAT", 8, false, false},
    FormatFacts{VK_FORMAT_R32G32_UINT, "R32G32_UINT", 8, false, false},
    FormatFacts{VK_FORMAT_R32G32B32A32_SFLOAT, "R32G32B32A32_SFLOAT", 16, false, false},
    FormatFacts{VK_FORMAT_B10G11R11_UFLOAT_PACK32, "B10G11R11_UFLOAT_PACK32", 4, false, false},
    FormatFacts{VK_FORMAT_D16_UNORM, "D16_UNORM", 2, true, false},
    FormatFacts{VK_FORMAT_X8_D24_UNORM_PACK32, "X8_D24_UNORM_PACK32", 4, true, false},
    FormatFacts{VK_FORMAT_D32_SFLOAT, "D32_SFLOAT", 4, true, false},
    FormatFacts{VK_FORMAT_S8_UINT, "S8_UINT", 1, false, true},
    FormatFacts{VK_FORMAT_D16_UNORM_S8_UINT, "D16_UNORM_S8_UINT", 4, true, true},
    FormatFacts{VK_FORMAT_D24_UNORM_S8_UINT, "D24_UNORM_S8_UINT", 4, true, true},
    FormatFacts{VK_FORMAT_D32_SFLOAT_S8_UINT, "D32_SFLOAT_S8_UINT", 8, true, true},
};

const FormatFacts* find(VkFormat format) {
    for (const auto& f : kFormats)
        if (f.format == format) return &f;
    return nullptr;
}

}  // namespace

bool hasDepth(VkFormat format) {
    const auto* f = find(format);
    return f && f->depth;
}

bool hasStencil(VkFormat format) {
    const auto* f = find(format);
    return f && f->stencil;
}

VkImageAspectFlags fullAspect(VkFormat format) {
    VkImageAspectFlags aspect = 0;
    if (hasDepth(format)) aspect |= VK_IMAGE_ASPECT_DEPTH_BIT;
    if (hasStencil(format)) aspect |= VK_IMAGE_ASPECT_STENCIL_BIT;
    return aspect ? aspect : VkImageAspectFlags{VK_IMAGE_ASPECT_COLOR_BIT};
}

bool isIntegerFormat(VkFormat format) {
    if (isDepthStencil(format)) return false;
    const std::string name = formatName(format);
    return name.ends_with("_UINT") || name.ends_with("_SINT");
}

uint32_t texelBytes(VkFormat format) {
    const auto* f = find(format);
    return f ? f->bytes : 0;
}

std::string formatName(VkFormat format) {
    if (const auto* f = find(format)) return std::string(f->name);
    return "format #" + std::to_string(static_cast<int>(format));
}

}  // namespace rg
