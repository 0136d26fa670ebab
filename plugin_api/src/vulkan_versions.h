#pragma once
// The Vulkan versions the plugin needs of the engine's instance and physical device, checked before
// any call that needs them: an instance made for 1.0 gives none of 1.3's entry points, and a 1.1
// call on it is itself a violation (UNASSIGNED-API-Version-Violation).
#include <vulkan/vulkan.h>

#include <string>

#include <lightscatter/lightscatter.h>

namespace lightscatter::detail {

// "1.3.250" (with "variant N " before it for a variant of Vulkan other than 0).
std::string versionText(uint32_t version);

// `given` (PluginCreateInfo::getInstanceProcAddr and the like), or the loader's; DeviceError where
// there is none.
PFN_vkGetInstanceProcAddr instanceProcAddr(PFN_vkGetInstanceProcAddr given);

// An instance-level entry point; DeviceError naming it where `getInstanceProcAddr` gives none.
PFN_vkVoidFunction instanceFunction(PFN_vkGetInstanceProcAddr getInstanceProcAddr,
                                    VkInstance instance, const char* name);

// `physical`'s properties (its apiVersion, its name), asked with Vulkan 1.0's
// vkGetPhysicalDeviceProperties.
VkPhysicalDeviceProperties deviceProperties(PFN_vkGetInstanceProcAddr getInstanceProcAddr,
                                            VkInstance instance, VkPhysicalDevice physical);

// Vulkan 1.3 or later (of variant 0, Vulkan itself).
bool atLeast13(uint32_t version);

// What an instance of `apiVersion` lacks, or empty: "VkApplicationInfo::apiVersion 1.3 or later
// (the instance's is 1.0.0)", for a message or a list.
std::string instanceVersionLack(uint32_t apiVersion);

// Refuses (InvalidInput) context.apiVersion below 1.3 without a Vulkan call, then a physical device
// below 1.3, asked with Vulkan 1.0's call alone.
void checkApiVersions(const PluginCreateInfo& info);

}  // namespace lightscatter::detail
