#pragma once
// A 2D image with memory of its own, named for debug utils: the one way the runtime, the plugin and
// the host allocate the images that outlive a frame graph.
#include <vulkan/vulkan.h>

#include <string>

#include "device.h"

namespace rg {

class OwnedImage {
  public:
    // One mip level, `layers` array layers (created with `flags`, e.g. CUBE_COMPATIBLE for six),
    // optimal tiling, device-local memory; `depth` above 1: a 3D image of that many slices.
    OwnedImage(const Device& device, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage,
               const std::string& name, uint32_t layers = 1, VkImageCreateFlags flags = 0,
               uint32_t depth = 1);
    ~OwnedImage();
    OwnedImage(const OwnedImage&) = delete;
    OwnedImage& operator=(const OwnedImage&) = delete;

    VkImage image() const { return image_; }
    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }
    VkImageUsageFlags usage() const { return usage_; }
    uint32_t layers() const { return layers_; }
    uint32_t depth() const { return depth_; }

  private:
    const Device& device_;
    VkFormat format_;
    VkExtent2D extent_;
    VkImageUsageFlags usage_;
    uint32_t layers_;
    uint32_t depth_;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize memoryBytes_ = 0;  // counted by deviceMemoryInUse()
};

}  // namespace rg
