#pragma once
// Device memory allocations that fail in the terms of what needed them. "vkAllocateMemory failed:
// VK_ERROR_OUT_OF_DEVICE_MEMORY" told a user nothing of which image, how large, or what the device
// has (issue #22); these name the object, its size and the heap, and refuse before calling Vulkan
// what the device can never hold (a block larger than its heap or than maxMemoryAllocationSize).
#include <vulkan/vulkan.h>

#include <string>

#include "device.h"

namespace rg {

// "2 GiB", "512 MiB", "37.5 KiB", "12 bytes".
std::string bytesText(VkDeviceSize bytes);

// Allocates `bytes` of memory type `memoryType` for `what` (e.g. "image 'host hdr color'
// (16384x16384 R16G16B16A16_SFLOAT)"). Throws OutOfDeviceMemory naming `what`, the size and the
// heap when the device cannot or did not give it. A fault point of fault_injection.h.
VkDeviceMemory allocateDeviceMemory(const Device& device, VkDeviceSize bytes, uint32_t memoryType,
                                    const std::string& what);

// A bind's result, where out of memory is a failed allocation too (lavapipe allocates at bind
// time): throws OutOfDeviceMemory like allocateDeviceMemory, other failures as VulkanError.
void checkBind(const Device& device, VkResult result, const char* call, VkDeviceSize bytes,
               uint32_t memoryType, const std::string& what);

// Throws VulkanError when a 2D image of `extent` and `layers` exceeds the device's
// maxImageDimension2D or maxImageArrayLayers, naming `what`: checked before vkCreateImage, which
// must not be given such an image (VUID-VkImageCreateInfo-extent-02252).
void checkImageLimits(const Device& device, VkExtent2D extent, uint32_t layers,
                      const std::string& what);
// The same for any image's create info (a 3D image against maxImageDimension3D), and then
// checkImageFormatLimits.
void checkImageLimits(const Device& device, const VkImageCreateInfo& info, const std::string& what);
// Throws VulkanError when vkGetPhysicalDeviceImageFormatProperties says the device makes no such
// image: not of this format, type, tiling, usage and flags, or not of this extent, layer count or
// size (maxResourceSize, VUID-VkImageCreateInfo-extent-02252 and the validation layer's
// InvalidFormatLimitsViolation). Checked before vkCreateImage.
void checkImageFormatLimits(const Device& device, const VkImageCreateInfo& info,
                            const std::string& what);

// A buffer or an image with memory of its own, bound at offset 0.
struct BoundBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize bytes = 0;  // of the memory
};
struct BoundImage {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize bytes = 0;
};

// The one way a buffer or an image is created with memory of its own: created from `info`, named
// `name` (its memory "`name` memory"), given memory of a type with `properties` and bound. Fails
// like allocateDeviceMemory and checkBind, naming `what`, and then leaves nothing behind; the
// creation and the allocation are fault points of fault_injection.h. The memory is not counted by
// deviceMemoryInUse(): owners that count do so themselves.
BoundBuffer createBoundBuffer(const Device& device, const VkBufferCreateInfo& info,
                              VkMemoryPropertyFlags properties, const std::string& name,
                              const std::string& what);
BoundImage createBoundImage(const Device& device, const VkImageCreateInfo& info,
                            VkMemoryPropertyFlags properties, const std::string& name,
                            const std::string& what);

}  // namespace rg
