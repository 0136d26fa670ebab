#pragma once
#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace rg {

class VulkanError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Out of device memory, said in the terms of what needed it (device_memory.h): which object, how
// many bytes, what the device has.
class OutOfDeviceMemory : public VulkanError {
  public:
    using VulkanError::VulkanError;
};

const char* resultName(VkResult result);

// The call as a message names it: "vkWaitForFences(device, ...)" for the runtime's
// "device_.vk().WaitForFences(device, ...)" (every call goes through loaded entry points).
std::string callText(const char* call);

// Throws VulkanError naming the call that failed and its result code.
inline void check(VkResult result, const char* call) {
    if (result != VK_SUCCESS) throw VulkanError(callText(call) + " failed: " + resultName(result));
}

}  // namespace rg

#define RG_VK(call) ::rg::check((call), #call)
