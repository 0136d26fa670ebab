#pragma once
// Device memory the runtime holds right now (every VkDeviceMemory allocated through it, by the
// graph executor, owned images and host buffers, minus what was freed), for soak tests and reports.
#include <cstdint>

#include <vulkan/vulkan.h>

namespace rg {

uint64_t deviceMemoryInUse();

namespace detail {
void countDeviceMemory(VkDeviceSize bytes);    // after a successful vkAllocateMemory
void uncountDeviceMemory(VkDeviceSize bytes);  // before the matching vkFreeMemory
}  // namespace detail

}  // namespace rg
