#pragma once
// A host-visible, coherent buffer for uploads and readbacks, imported into graphs by engines and
// tests.
#include <vulkan/vulkan.h>

#include <string>

#include "device.h"
#include "resources.h"

namespace rg {

class HostBuffer {
  public:
    HostBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
               const std::string& name);
    ~HostBuffer();
    HostBuffer(const HostBuffer&) = delete;
    HostBuffer& operator=(const HostBuffer&) = delete;

    VkBuffer buffer() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    void* data() const { return mapped_; }

    // Import description: written by transfers in the graph, read by the host afterwards.
    ImportedBuffer asReadback() const;

  private:
    const Device& device_;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize memoryBytes_ = 0;  // counted by deviceMemoryInUse()
    VkDeviceSize size_;
    VkBufferUsageFlags usage_;
    void* mapped_ = nullptr;
};

}  // namespace rg
