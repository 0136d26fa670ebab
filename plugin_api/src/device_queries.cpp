// What a physical device has of what the plugin needs and may use, asked before the engine makes a
// device of it: the features to ask for (the optional ones it has) and what it lacks. Below Vulkan
// 1.3, on the instance's side or the device's, only Vulkan 1.0 calls are made.
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "device_features.h"
#include "vulkan_versions.h"

namespace lightscatter {
namespace {

template <typename Pfn>
Pfn load(PFN_vkGetInstanceProcAddr getInstanceProcAddr, VkInstance instance, const char* name) {
    return reinterpret_cast<Pfn>(detail::instanceFunction(getInstanceProcAddr, instance, name));
}

VkPhysicalDeviceFeatures coreFeaturesOf(VkInstance instance, VkPhysicalDevice physical,
                                        PFN_vkGetInstanceProcAddr given) {
    const PFN_vkGetInstanceProcAddr gipa = detail::instanceProcAddr(given);
    VkPhysicalDeviceFeatures has{};
    load<PFN_vkGetPhysicalDeviceFeatures>(gipa, instance, "vkGetPhysicalDeviceFeatures")(physical,
                                                                                         &has);
    return has;
}

std::vector<std::string> extensionsLacking(PFN_vkGetInstanceProcAddr gipa, VkInstance instance,
                                           VkPhysicalDevice physical) {
    const auto enumerate = load<PFN_vkEnumerateDeviceExtensionProperties>(
        gipa, instance, "vkEnumerateDeviceExtensionProperties");
    uint32_t n = 0;
    enumerate(physical, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> offered(n);
    enumerate(physical, nullptr, &n, offered.data());
    offered.resize(n);
    std::vector<std::string> lacking;
    for (const char* name : requiredDeviceExtensions())
        if (std::none_of(offered.begin(), offered.end(), [&](const VkExtensionProperties& e) {
                return std::strcmp(e.extensionName, name) == 0;
            }))
            lacking.push_back(name);
    return lacking;
}

// The plugin records graphics and compute work on one queue and times it.
bool hasPluginQueue(PFN_vkGetInstanceProcAddr gipa, VkInstance instance,
                    VkPhysicalDevice physical) {
    const auto families = load<PFN_vkGetPhysicalDeviceQueueFamilyProperties>(
        gipa, instance, "vkGetPhysicalDeviceQueueFamilyProperties");
    uint32_t n = 0;
    families(physical, &n, nullptr);
    std::vector<VkQueueFamilyProperties> all(n);
    families(physical, &n, all.data());
    all.resize(n);
    const VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    return std::any_of(all.begin(), all.end(), [&](const VkQueueFamilyProperties& f) {
        return (f.queueFlags & wanted) == wanted && f.timestampValidBits > 0;
    });
}

}  // namespace

DeviceFeatures requiredDeviceFeatures(VkInstance instance, VkPhysicalDevice physical,
                                      PFN_vkGetInstanceProcAddr getInstanceProcAddr) {
    const VkPhysicalDeviceFeatures has = coreFeaturesOf(instance, physical, getInstanceProcAddr);
    DeviceFeatures f = requiredDeviceFeatures();
    detail::addOptionalFeatures(f.core.features, has);
    f.chain();
    return f;
}

void mergeRequiredDeviceFeatures(VkPhysicalDeviceFeatures& core, void* pNext, VkInstance instance,
                                 VkPhysicalDevice physical,
                                 PFN_vkGetInstanceProcAddr getInstanceProcAddr) {
    detail::mergeWithOptional(core, pNext, coreFeaturesOf(instance, physical, getInstanceProcAddr));
}

std::vector<std::string> missingDeviceFeatures(VkInstance instance, VkPhysicalDevice physical,
                                               uint32_t instanceApiVersion,
                                               PFN_vkGetInstanceProcAddr getInstanceProcAddr) {
    const PFN_vkGetInstanceProcAddr gipa = detail::instanceProcAddr(getInstanceProcAddr);
    std::vector<std::string> lacks;
    const std::string instanceLack = detail::instanceVersionLack(instanceApiVersion);
    if (!instanceLack.empty()) lacks.push_back(instanceLack);
    const VkPhysicalDeviceProperties p = detail::deviceProperties(gipa, instance, physical);
    const bool device13 = detail::atLeast13(p.apiVersion);
    if (!device13)
        lacks.push_back("Vulkan 1.3 (the device offers " + detail::versionText(p.apiVersion) + ")");
    for (std::string& e : extensionsLacking(gipa, instance, physical)) lacks.push_back(e);
    // Vulkan 1.2's and 1.3's features can be asked for only with 1.1's call, on an instance and a
    // device of 1.3 (the structures that hold them are 1.2's and 1.3's).
    const bool whole = instanceLack.empty() && device13;
    DeviceFeatures has;
    has.core.features = {};
    if (whole)
        load<PFN_vkGetPhysicalDeviceFeatures2>(gipa, instance, "vkGetPhysicalDeviceFeatures2")(
            physical, has.chain());
    else
        has.core.features = coreFeaturesOf(instance, physical, gipa);
    for (std::string& f : detail::featuresOff(*has.chain(), !whole)) lacks.push_back(f);
    if (!hasPluginQueue(gipa, instance, physical))
        lacks.push_back("a queue family with graphics, compute and timestamps");
    return lacks;
}

}  // namespace lightscatter
