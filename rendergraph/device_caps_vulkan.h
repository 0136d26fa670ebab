#pragma once
// DeviceCaps answered by a real device: its format features and the memory requirements it
// reports for exactly the images and buffers the executor will create.
#include "device.h"
#include "device_caps.h"

namespace rg {

class VulkanDeviceCaps : public DeviceCaps {
  public:
    explicit VulkanDeviceCaps(const Device& device) : device_(device) {}
    std::string name() const override { return "device '" + device_.name() + "'"; }
    bool exact() const override { return true; }
    VkFormatFeatureFlags2 optimalFeatures(VkFormat format) const override;
    MemoryRequirements imageRequirements(const VkImageCreateInfo& info) const override;
    MemoryRequirements bufferRequirements(const VkBufferCreateInfo& info) const override;
    VkDeviceSize bufferImageGranularity() const override {
        return device_.properties().limits.bufferImageGranularity;
    }
    uint32_t memoryTypeFor(uint32_t typeBits) const override {
        return device_.findMemoryType(typeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    }

  private:
    const Device& device_;
};

}  // namespace rg
