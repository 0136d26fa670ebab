#include "vulkan_versions.h"

#include "rendergraph/vk_error.h"
#include "rendergraph/vulkan_functions.h"

namespace lightscatter::detail {

bool atLeast13(uint32_t v) {
    return VK_API_VERSION_VARIANT(v) == 0 &&
           (VK_API_VERSION_MAJOR(v) > 1 ||
            (VK_API_VERSION_MAJOR(v) == 1 && VK_API_VERSION_MINOR(v) >= 3));
}

std::string versionText(uint32_t v) {
    const std::string variant = VK_API_VERSION_VARIANT(v) == 0
                                    ? std::string()
                                    : "variant " + std::to_string(VK_API_VERSION_VARIANT(v)) + " ";
    return variant + std::to_string(VK_API_VERSION_MAJOR(v)) + "." +
           std::to_string(VK_API_VERSION_MINOR(v)) + "." + std::to_string(VK_API_VERSION_PATCH(v));
}

PFN_vkGetInstanceProcAddr instanceProcAddr(PFN_vkGetInstanceProcAddr given) {
    if (given) return given;
    try {
        return rg::loaderProcAddr();
    } catch (const rg::VulkanError& e) {
        throw DeviceError(std::string("lightscatter: ") + e.what());
    }
}

PFN_vkVoidFunction instanceFunction(PFN_vkGetInstanceProcAddr getInstanceProcAddr,
                                    VkInstance instance, const char* name) {
    const PFN_vkVoidFunction f = getInstanceProcAddr(instance, name);
    if (!f)
        throw DeviceError(std::string("lightscatter: the Vulkan entry point ") + name +
                          " is not given by vkGetInstanceProcAddr of the instance");
    return f;
}

VkPhysicalDeviceProperties deviceProperties(PFN_vkGetInstanceProcAddr getInstanceProcAddr,
                                            VkInstance instance, VkPhysicalDevice physical) {
    const auto properties = reinterpret_cast<PFN_vkGetPhysicalDeviceProperties>(
        instanceFunction(getInstanceProcAddr, instance, "vkGetPhysicalDeviceProperties"));
    VkPhysicalDeviceProperties p{};
    properties(physical, &p);
    return p;
}

std::string instanceVersionLack(uint32_t apiVersion) {
    if (atLeast13(apiVersion)) return {};
    return "VkApplicationInfo::apiVersion 1.3 or later (the instance's is " +
           (apiVersion == 0 ? std::string("0, which Vulkan reads as 1.0")
                            : versionText(apiVersion)) +
           ")";
}

void checkApiVersions(const PluginCreateInfo& info) {
    const VulkanContext& c = info.context;
    if (c.apiVersion == 0)
        throw InvalidInput(
            "lightscatter: context.apiVersion is 0: it must be the VkApplicationInfo::apiVersion "
            "the instance was created with (Vulkan cannot be asked for it), VK_API_VERSION_1_3 or "
            "later; 0 there is Vulkan 1.0, whose instance gives none of the Vulkan 1.3 entry "
            "points the plugin calls");
    if (!atLeast13(c.apiVersion))
        throw InvalidInput("lightscatter: context.apiVersion is " + versionText(c.apiVersion) +
                           ": the instance must be created with VkApplicationInfo::apiVersion "
                           "VK_API_VERSION_1_3 or later; one created for " +
                           versionText(c.apiVersion) +
                           " gives none of the Vulkan 1.3 entry points the plugin calls "
                           "(vkQueueSubmit2, vkCmdPipelineBarrier2, ...), whatever its device "
                           "offers");
    const VkPhysicalDeviceProperties p =
        deviceProperties(instanceProcAddr(info.getInstanceProcAddr), c.instance, c.physicalDevice);
    if (!atLeast13(p.apiVersion))
        throw InvalidInput("lightscatter: context.physicalDevice '" + std::string(p.deviceName) +
                           "' offers Vulkan " + versionText(p.apiVersion) +
                           " (VkPhysicalDeviceProperties::apiVersion): the plugin needs a device "
                           "of Vulkan 1.3 or later");
}

}  // namespace lightscatter::detail
