#pragma once
// What the compiler needs to know about a device: format features and memory requirements. A
// Vulkan-backed implementation answers for a real device; OfflineDeviceCaps answers without one
// (graph-validation tests, memory budgets on a machine with no GPU), modelled on a typical
// Vulkan 1.3 desktop device and labelled as an estimate wherever it is reported.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <initializer_list>
#include <string>

namespace rg {

struct MemoryRequirements {
    VkDeviceSize size = 0;
    VkDeviceSize alignment = 1;
    uint32_t memoryTypeBits = ~0u;
};

class DeviceCaps {
  public:
    virtual ~DeviceCaps() = default;
    virtual std::string name() const = 0;
    // True when the sizes come from the device itself rather than an estimate.
    virtual bool exact() const = 0;
    virtual VkFormatFeatureFlags2 optimalFeatures(VkFormat format) const = 0;
    virtual MemoryRequirements imageRequirements(const VkImageCreateInfo& info) const = 0;
    virtual MemoryRequirements bufferRequirements(const VkBufferCreateInfo& info) const = 0;
    virtual VkDeviceSize bufferImageGranularity() const = 0;
    // The device-local memory type to place transient resources with these type bits in.
    virtual uint32_t memoryTypeFor(uint32_t typeBits) const = 0;
};

// A device without a GPU behind it. Formats follow what lavapipe and current desktop GPUs offer;
// D24_UNORM_S8_UINT can be switched off to model devices that lack it.
class OfflineDeviceCaps : public DeviceCaps {
  public:
    explicit OfflineDeviceCaps(bool hasD24S8 = true) : hasD24S8_(hasD24S8) {}
    std::string name() const override { return "offline estimate (no device)"; }
    bool exact() const override { return false; }
    VkFormatFeatureFlags2 optimalFeatures(VkFormat format) const override;
    MemoryRequirements imageRequirements(const VkImageCreateInfo& info) const override;
    MemoryRequirements bufferRequirements(const VkBufferCreateInfo& info) const override;
    VkDeviceSize bufferImageGranularity() const override { return 1024; }
    uint32_t memoryTypeFor(uint32_t) const override { return 0; }

    // Lets tests remove features to provoke the format rule.
    void removeFeatures(VkFormat format, VkFormatFeatureFlags2 features);

  private:
    bool hasD24S8_;
    VkFormat removedFormat_ = VK_FORMAT_UNDEFINED;
    VkFormatFeatureFlags2 removed_ = 0;
};

}  // namespace rg

namespace rg {

// The first format in `candidates` that has every feature in `features`, or VK_FORMAT_UNDEFINED.
VkFormat firstSupported(const DeviceCaps& caps, std::initializer_list<VkFormat> candidates,
                        VkFormatFeatureFlags2 features);

}  // namespace rg
