#pragma once
// What the engine enabled on its device of the features the plugin may use but never requires
// (VulkanContext::enabledFeatures): a pass takes the path of such a feature only where it is on.

namespace ls {

struct DeviceCapabilities {
    // VkPhysicalDeviceFeatures::dualSrcBlend: a blend with the fragment's two outputs as sources.
    bool dualSourceBlend = false;
    bool operator==(const DeviceCapabilities&) const = default;
};

}  // namespace ls
