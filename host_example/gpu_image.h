#pragma once
// An engine-owned image with its own memory: the host's depth, HDR color, shadow map and Lin output,
// which it hands to the plugin each frame.
#include <vulkan/vulkan.h>

#include <string>

#include "rendergraph/device.h"

namespace host {

class GpuImage {
public:
    GpuImage(const rg::Device& device, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage,
             const std::string& name);
    ~GpuImage();
    GpuImage(const GpuImage&) = delete;
    GpuImage& operator=(const GpuImage&) = delete;

    VkImage image() const { return image_; }
    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }
    VkImageUsageFlags usage() const { return usage_; }

private:
    const rg::Device& device_;
    VkFormat format_;
    VkExtent2D extent_;
    VkImageUsageFlags usage_;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
};

}  // namespace host
