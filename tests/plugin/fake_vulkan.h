#pragma once
// A physical device of the test's own behind a vkGetInstanceProcAddr, for the device contract
// without a GPU: it answers Vulkan 1.0's queries (and vkGetPhysicalDeviceFeatures2) from what the
// test sets, and records each entry point asked for and called, so that a test sees which calls
// the plugin made before it refused.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace fake_vulkan {

struct Device {
    uint32_t apiVersion = VK_API_VERSION_1_3;
    VkPhysicalDeviceFeatures core{};  // reset() turns every feature on
    VkPhysicalDeviceVulkan12Features vulkan12{};
    VkPhysicalDeviceVulkan13Features vulkan13{};
    bool pushDescriptor = true;  // offers VK_KHR_push_descriptor
    bool timestamps = true;      // its graphics + compute queue family has timestamps
    std::vector<std::string> asked, called;
};

// The device the fake answers for, reset() to one that has everything.
Device& device();
void reset();

// The fake's vkGetInstanceProcAddr: null for anything but the queries above.
PFN_vkGetInstanceProcAddr getInstanceProcAddr();

// Handles that are not null, for a context the plugin refuses before it uses them.
VkInstance instance();
VkPhysicalDevice physicalDevice();
VkDevice logicalDevice();
VkQueue queue();

}  // namespace fake_vulkan
