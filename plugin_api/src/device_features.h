#pragma once
// What the plugin needs of the engine's device, checked against what the engine enabled, and what
// it uses where the engine enabled it.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "shared/device_capabilities.h"

namespace lightscatter::detail {

// Throws InvalidInput naming every feature the plugin needs that `enabled` (the chain an engine
// created its device with) does not turn on.
void checkEnabledFeatures(const VkPhysicalDeviceFeatures2* enabled);

// The names of the features the plugin needs that `chain` does not turn on, in any of its
// structures; `coreOnly`: of VkPhysicalDeviceFeatures's alone (all a Vulkan 1.0 query gives).
std::vector<std::string> featuresOff(const VkPhysicalDeviceFeatures2& chain, bool coreOnly);

// Turns on in `core` each optional feature (dualSrcBlend) that `has` has.
void addOptionalFeatures(VkPhysicalDeviceFeatures& core, const VkPhysicalDeviceFeatures& has);

// mergeRequiredDeviceFeatures(core, pNext) with the optional features `has` has.
void mergeWithOptional(VkPhysicalDeviceFeatures& core, void* pNext,
                       const VkPhysicalDeviceFeatures& has);

// What the passes may use of the optional features, as `enabled` (VulkanContext::enabledFeatures,
// checked) turns them on.
ls::DeviceCapabilities enabledCapabilities(const VkPhysicalDeviceFeatures2& enabled);

}  // namespace lightscatter::detail
