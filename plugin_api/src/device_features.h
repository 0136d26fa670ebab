#pragma once
// What the plugin needs of the engine's device, checked against what the engine enabled.
#include <vulkan/vulkan.h>

namespace lightscatter::detail {

// Throws InvalidInput naming every feature the plugin needs that `enabled` (the chain an engine
// created its device with) does not turn on.
void checkEnabledFeatures(const VkPhysicalDeviceFeatures2* enabled);

}  // namespace lightscatter::detail
