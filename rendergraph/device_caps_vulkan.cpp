#include "device_caps_vulkan.h"

namespace rg {

VkFormatFeatureFlags2 VulkanDeviceCaps::optimalFeatures(VkFormat format) const {
    VkFormatProperties3 props3{VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_3};
    VkFormatProperties2 props{VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_2};
    props.pNext = &props3;
    device_.vk().GetPhysicalDeviceFormatProperties2(device_.physical(), format, &props);
    return props3.optimalTilingFeatures;
}

MemoryRequirements VulkanDeviceCaps::imageRequirements(const VkImageCreateInfo& info) const {
    VkDeviceImageMemoryRequirements query{VK_STRUCTURE_TYPE_DEVICE_IMAGE_MEMORY_REQUIREMENTS};
    query.pCreateInfo = &info;
    VkMemoryRequirements2 req{VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2};
    device_.vk().GetDeviceImageMemoryRequirements(device_.device(), &query, &req);
    return {req.memoryRequirements.size, req.memoryRequirements.alignment,
            req.memoryRequirements.memoryTypeBits};
}

MemoryRequirements VulkanDeviceCaps::bufferRequirements(const VkBufferCreateInfo& info) const {
    VkDeviceBufferMemoryRequirements query{VK_STRUCTURE_TYPE_DEVICE_BUFFER_MEMORY_REQUIREMENTS};
    query.pCreateInfo = &info;
    VkMemoryRequirements2 req{VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2};
    device_.vk().GetDeviceBufferMemoryRequirements(device_.device(), &query, &req);
    return {req.memoryRequirements.size, req.memoryRequirements.alignment,
            req.memoryRequirements.memoryTypeBits};
}

}  // namespace rg
