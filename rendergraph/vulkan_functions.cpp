#include "vulkan_functions.h"

#include <dlfcn.h>

#include <string>

#include "vk_error.h"

namespace rg {
namespace {

[[noreturn]] void missing(const char* name, const char* from) {
    throw VulkanError(std::string("the Vulkan entry point vk") + name + " is not given by " + from);
}

}  // namespace

PFN_vkGetInstanceProcAddr loaderProcAddr() {
    static const PFN_vkGetInstanceProcAddr found = [] {
        void* library = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
        if (!library) library = dlopen("libvulkan.so", RTLD_NOW | RTLD_LOCAL);
        return library ? reinterpret_cast<PFN_vkGetInstanceProcAddr>(
                             dlsym(library, "vkGetInstanceProcAddr"))
                       : nullptr;
    }();
    if (!found)
        throw VulkanError(
            "no Vulkan loader: libvulkan.so.1 was not found (install libvulkan1, or give the "
            "engine's vkGetInstanceProcAddr)");
    return found;
}

void VulkanFunctions::loadGlobal(PFN_vkGetInstanceProcAddr getInstanceProcAddr) {
    GetInstanceProcAddr = getInstanceProcAddr ? getInstanceProcAddr : loaderProcAddr();
#define RG_VK_LOAD(name)                                                                    \
    name = reinterpret_cast<PFN_vk##name>(GetInstanceProcAddr(VK_NULL_HANDLE, "vk" #name)); \
    if (!name) missing(#name, "vkGetInstanceProcAddr(NULL)");
    RG_VK_GLOBAL_FUNCTIONS(RG_VK_LOAD)
#undef RG_VK_LOAD
}

void VulkanFunctions::loadInstance(VkInstance instance) {
#define RG_VK_LOAD(name)                                                              \
    name = reinterpret_cast<PFN_vk##name>(GetInstanceProcAddr(instance, "vk" #name)); \
    if (!name) missing(#name, "vkGetInstanceProcAddr of the instance");
    RG_VK_INSTANCE_FUNCTIONS(RG_VK_LOAD)
#undef RG_VK_LOAD
#define RG_VK_LOAD_OPTIONAL(name) \
    name = reinterpret_cast<PFN_vk##name>(GetInstanceProcAddr(instance, "vk" #name));
    RG_VK_DEBUG_UTILS_FUNCTIONS(RG_VK_LOAD_OPTIONAL)
#undef RG_VK_LOAD_OPTIONAL
}

// What is missing is said as what it is, core Vulkan or the extension's: vkGetDeviceProcAddr gives
// a core function only where the instance's and the device's versions have it, and an extension's
// only where the device enabled the extension, which no query tells afterwards.
void VulkanFunctions::loadDevice(VkDevice device) {
#define RG_VK_LOAD(name)                                                          \
    name = reinterpret_cast<PFN_vk##name>(GetDeviceProcAddr(device, "vk" #name)); \
    if (!name) missing(#name, from);
    const char* from = "vkGetDeviceProcAddr of the device (a core Vulkan function)";
    RG_VK_DEVICE_FUNCTIONS(RG_VK_LOAD)
    from = "vkGetDeviceProcAddr of the device (VK_KHR_push_descriptor's)";
    RG_VK_PUSH_DESCRIPTOR_FUNCTIONS(RG_VK_LOAD)
#undef RG_VK_LOAD
}

}  // namespace rg
