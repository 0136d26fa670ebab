#include "owned_image.h"

#include "device_memory.h"
#include "format_info.h"
#include "memory_counter.h"

namespace rg {

OwnedImage::OwnedImage(const rg::Device& device, VkFormat format, VkExtent2D extent,
                       VkImageUsageFlags usage, const std::string& name, uint32_t layers,
                       VkImageCreateFlags flags, uint32_t depth)
    : device_(device),
      format_(format),
      extent_(extent),
      usage_(usage),
      layers_(layers),
      depth_(depth) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.flags = flags;
    info.imageType = depth > 1 ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, depth};
    info.mipLevels = 1;
    info.arrayLayers = layers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    const std::string what =
        "image '" + name + "' (" + std::to_string(extent.width) + "x" +
        std::to_string(extent.height) + (depth > 1 ? "x" + std::to_string(depth) : "") + " " +
        formatName(format) + (layers > 1 ? ", " + std::to_string(layers) + " layers" : "") + ")";
    checkImageLimits(device, info, "image '" + name + "'");
    const BoundImage bound =
        createBoundImage(device, info, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, name, what);
    image_ = bound.image;
    memory_ = bound.memory;
    memoryBytes_ = bound.bytes;
    detail::countDeviceMemory(memoryBytes_);
}

OwnedImage::~OwnedImage() {
    device_.vk().DestroyImage(device_.device(), image_, device_.allocator());
    detail::uncountDeviceMemory(memoryBytes_);
    device_.vk().FreeMemory(device_.device(), memory_, device_.allocator());
}

}  // namespace rg
