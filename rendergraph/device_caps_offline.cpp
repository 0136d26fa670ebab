#include <algorithm>

#include "device_caps.h"
#include "format_info.h"

namespace rg {
namespace {

constexpr VkFormatFeatureFlags2 kSampled = VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT |
                                           VK_FORMAT_FEATURE_2_TRANSFER_SRC_BIT |
                                           VK_FORMAT_FEATURE_2_TRANSFER_DST_BIT;
constexpr VkFormatFeatureFlags2 kFilter = VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
constexpr VkFormatFeatureFlags2 kStorage = VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT;
constexpr VkFormatFeatureFlags2 kColor = VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT;
constexpr VkFormatFeatureFlags2 kBlend = VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BLEND_BIT;
constexpr VkFormatFeatureFlags2 kDepth = VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT;

VkDeviceSize alignUp(VkDeviceSize v, VkDeviceSize a) {
    return (v + a - 1) / a * a;
}

}  // namespace

VkFormatFeatureFlags2 OfflineDeviceCaps::optimalFeatures(VkFormat format) const {
    VkFormatFeatureFlags2 f = 0;
    switch (format) {
        case VK_FORMAT_R8G8B8A8_UNORM:
        case VK_FORMAT_R8G8_UNORM:  // the tiling noise: storage with
                                    // shaderStorageImageExtendedFormats
        case VK_FORMAT_R16G16B16A16_SFLOAT:
        case VK_FORMAT_R16G16_SFLOAT:
        case VK_FORMAT_R32G32_SFLOAT:
        case VK_FORMAT_R32_SFLOAT:
        case VK_FORMAT_R16_SFLOAT:
        case VK_FORMAT_R32G32B32A32_SFLOAT:
            f = kSampled | kFilter | kStorage | kColor | kBlend;
            break;
        case VK_FORMAT_B8G8R8A8_UNORM:
        case VK_FORMAT_R8G8B8A8_SRGB:
        case VK_FORMAT_B8G8R8A8_SRGB:
        case VK_FORMAT_B10G11R11_UFLOAT_PACK32:  // an engine's HDR target, blended into
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
            f = kSampled | kFilter | kColor | kBlend;
            break;
        case VK_FORMAT_R16G16_UNORM:
            f = kSampled | kFilter | kColor | kBlend;
            break;
        case VK_FORMAT_R16G16_UINT:
        case VK_FORMAT_R32_UINT:
        case VK_FORMAT_R32G32_UINT:
        case VK_FORMAT_R16_UINT:
            f = kSampled | kStorage | kColor;
            break;
        case VK_FORMAT_D16_UNORM:
        case VK_FORMAT_S8_UINT:
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_D32_SFLOAT_S8_UINT:
            f = kSampled | kDepth;
            break;
        case VK_FORMAT_D24_UNORM_S8_UINT:
            f = hasD24S8_ ? (kSampled | kDepth) : 0;
            break;
        default:
            break;
    }
    if (format == removedFormat_) f &= ~removed_;
    return f;
}

void OfflineDeviceCaps::removeFeatures(VkFormat format, VkFormatFeatureFlags2 features) {
    removedFormat_ = format;
    removed_ = features;
}

// Tightly packed texels, each mip level rounded to 256 bytes, the whole to 64 KiB: the shape of
// what desktop drivers report for optimally tiled render targets.
MemoryRequirements OfflineDeviceCaps::imageRequirements(const VkImageCreateInfo& info) const {
    const VkDeviceSize texel = std::max<uint32_t>(texelBytes(info.format), 1);
    VkDeviceSize total = 0;
    uint32_t w = info.extent.width, h = info.extent.height;
    for (uint32_t level = 0; level < info.mipLevels; ++level) {
        total += alignUp(texel * w * h * std::max(info.extent.depth, 1u), 256);
        w = std::max(1u, w / 2);
        h = std::max(1u, h / 2);
    }
    total *= info.arrayLayers;
    return {alignUp(total, 65536), 65536, 1u};
}

MemoryRequirements OfflineDeviceCaps::bufferRequirements(const VkBufferCreateInfo& info) const {
    return {alignUp(info.size, 256), 256, 1u};
}

}  // namespace rg

namespace rg {

VkFormat firstSupported(const DeviceCaps& caps, std::initializer_list<VkFormat> candidates,
                        VkFormatFeatureFlags2 features) {
    for (VkFormat f : candidates)
        if ((caps.optimalFeatures(f) & features) == features) return f;
    return VK_FORMAT_UNDEFINED;
}

}  // namespace rg
