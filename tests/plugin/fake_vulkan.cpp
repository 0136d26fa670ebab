#include "fake_vulkan.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace fake_vulkan {
namespace {

Device gDevice;

template <typename T>
void allOnAfterChain(T& s) {
    // Every VkBool32 after sType and pNext.
    auto* flags = reinterpret_cast<VkBool32*>(reinterpret_cast<char*>(&s) + offsetof(T, pNext) +
                                              sizeof(void*));
    const size_t n = (sizeof(T) - offsetof(T, pNext) - sizeof(void*)) / sizeof(VkBool32);
    for (size_t i = 0; i < n; ++i) flags[i] = VK_TRUE;
}

void allOn(VkPhysicalDeviceFeatures& f) {
    auto* flags = reinterpret_cast<VkBool32*>(&f);
    for (size_t i = 0; i < sizeof f / sizeof(VkBool32); ++i) flags[i] = VK_TRUE;
}

template <typename T>
void copyKeepingChain(T* into, const T& from) {
    void* next = into->pNext;
    *into = from;
    into->pNext = next;
}

VKAPI_ATTR void VKAPI_CALL properties(VkPhysicalDevice, VkPhysicalDeviceProperties* p) {
    gDevice.called.push_back("vkGetPhysicalDeviceProperties");
    *p = {};
    p->apiVersion = gDevice.apiVersion;
    std::strcpy(p->deviceName, "fake device");
}

VKAPI_ATTR void VKAPI_CALL features(VkPhysicalDevice, VkPhysicalDeviceFeatures* f) {
    gDevice.called.push_back("vkGetPhysicalDeviceFeatures");
    *f = gDevice.core;
}

VKAPI_ATTR void VKAPI_CALL features2(VkPhysicalDevice, VkPhysicalDeviceFeatures2* f) {
    gDevice.called.push_back("vkGetPhysicalDeviceFeatures2");
    f->features = gDevice.core;
    for (auto* s = static_cast<VkBaseOutStructure*>(f->pNext); s; s = s->pNext) {
        if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES)
            copyKeepingChain(reinterpret_cast<VkPhysicalDeviceVulkan12Features*>(s),
                             gDevice.vulkan12);
        if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES)
            copyKeepingChain(reinterpret_cast<VkPhysicalDeviceVulkan13Features*>(s),
                             gDevice.vulkan13);
    }
}

VKAPI_ATTR VkResult VKAPI_CALL extensions(VkPhysicalDevice, const char*, uint32_t* n,
                                          VkExtensionProperties* p) {
    gDevice.called.push_back("vkEnumerateDeviceExtensionProperties");
    const uint32_t offered = gDevice.pushDescriptor ? 1 : 0;
    if (!p) {
        *n = offered;
        return VK_SUCCESS;
    }
    if (offered && *n > 0) {
        *p = {};
        std::strcpy(p->extensionName, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME);
    }
    *n = offered;
    return VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL queueFamilies(VkPhysicalDevice, uint32_t* n,
                                         VkQueueFamilyProperties* p) {
    gDevice.called.push_back("vkGetPhysicalDeviceQueueFamilyProperties");
    if (!p) {
        *n = 1;
        return;
    }
    *p = {};
    p->queueFlags = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    p->queueCount = 1;
    p->timestampValidBits = gDevice.timestamps ? 64 : 0;
    *n = 1;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL getProcAddr(VkInstance, const char* name) {
    gDevice.asked.push_back(name);
    const std::string n = name;
    if (n == "vkGetPhysicalDeviceProperties")
        return reinterpret_cast<PFN_vkVoidFunction>(&properties);
    if (n == "vkGetPhysicalDeviceFeatures") return reinterpret_cast<PFN_vkVoidFunction>(&features);
    if (n == "vkGetPhysicalDeviceFeatures2")
        return reinterpret_cast<PFN_vkVoidFunction>(&features2);
    if (n == "vkEnumerateDeviceExtensionProperties")
        return reinterpret_cast<PFN_vkVoidFunction>(&extensions);
    if (n == "vkGetPhysicalDeviceQueueFamilyProperties")
        return reinterpret_cast<PFN_vkVoidFunction>(&queueFamilies);
    return nullptr;
}

template <typename Handle>
Handle fakeHandle(uintptr_t value) {
    return reinterpret_cast<Handle>(value);
}

}  // namespace

Device& device() {
    return gDevice;
}

void reset() {
    gDevice = Device{};
    allOn(gDevice.core);
    gDevice.vulkan12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
    gDevice.vulkan13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
    allOnAfterChain(gDevice.vulkan12);
    allOnAfterChain(gDevice.vulkan13);
}

PFN_vkGetInstanceProcAddr getInstanceProcAddr() {
    return &getProcAddr;
}

VkInstance instance() {
    return fakeHandle<VkInstance>(0x10);
}
VkPhysicalDevice physicalDevice() {
    return fakeHandle<VkPhysicalDevice>(0x20);
}
VkDevice logicalDevice() {
    return fakeHandle<VkDevice>(0x30);
}
VkQueue queue() {
    return fakeHandle<VkQueue>(0x40);
}

}  // namespace fake_vulkan
