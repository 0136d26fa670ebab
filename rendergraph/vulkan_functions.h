#pragma once
// Every Vulkan entry point the runtime, the passes and the plugin call, loaded at run time from a
// vkGetInstanceProcAddr: an engine's own (which may count, wrap or trace the calls), or the
// loader's, opened with dlopen when none is given. The library is compiled with VK_NO_PROTOTYPES,
// so it binds no vk* symbol and works in an engine that links no loader (volk and the like).
// Device-level entry points come from vkGetDeviceProcAddr of the device they serve.
#include <vulkan/vulkan.h>

namespace rg {

// Global entry points (vkGetInstanceProcAddr(NULL, ...)).
#define RG_VK_GLOBAL_FUNCTIONS(X)           \
    X(CreateInstance)                       \
    X(EnumerateInstanceExtensionProperties) \
    X(EnumerateInstanceLayerProperties)

// Instance-level entry points.
#define RG_VK_INSTANCE_FUNCTIONS(X)           \
    X(DestroyInstance)                        \
    X(EnumeratePhysicalDevices)               \
    X(EnumerateDeviceExtensionProperties)     \
    X(GetPhysicalDeviceProperties)            \
    X(GetPhysicalDeviceProperties2)           \
    X(GetPhysicalDeviceFeatures)              \
    X(GetPhysicalDeviceFeatures2)             \
    X(GetPhysicalDeviceFormatProperties2)     \
    X(GetPhysicalDeviceImageFormatProperties) \
    X(GetPhysicalDeviceMemoryProperties)      \
    X(GetPhysicalDeviceQueueFamilyProperties) \
    X(CreateDevice)                           \
    X(GetDeviceProcAddr)

// VK_EXT_debug_utils: null where the instance did not enable it.
#define RG_VK_DEBUG_UTILS_FUNCTIONS(X) \
    X(CreateDebugUtilsMessengerEXT)    \
    X(DestroyDebugUtilsMessengerEXT)   \
    X(SetDebugUtilsObjectNameEXT)      \
    X(CmdBeginDebugUtilsLabelEXT)      \
    X(CmdEndDebugUtilsLabelEXT)

// Device-level entry points of core Vulkan (1.0 to 1.3).
#define RG_VK_DEVICE_FUNCTIONS(X)        \
    X(DestroyDevice)                     \
    X(GetDeviceQueue)                    \
    X(DeviceWaitIdle)                    \
    X(QueueSubmit2)                      \
    X(QueueWaitIdle)                     \
    X(AllocateMemory)                    \
    X(FreeMemory)                        \
    X(MapMemory)                         \
    X(BindBufferMemory)                  \
    X(BindImageMemory)                   \
    X(GetBufferMemoryRequirements)       \
    X(GetImageMemoryRequirements)        \
    X(GetDeviceBufferMemoryRequirements) \
    X(GetDeviceImageMemoryRequirements)  \
    X(CreateBuffer)                      \
    X(DestroyBuffer)                     \
    X(CreateImage)                       \
    X(DestroyImage)                      \
    X(CreateImageView)                   \
    X(DestroyImageView)                  \
    X(CreateSampler)                     \
    X(DestroySampler)                    \
    X(CreateShaderModule)                \
    X(DestroyShaderModule)               \
    X(CreateDescriptorSetLayout)         \
    X(DestroyDescriptorSetLayout)        \
    X(CreatePipelineLayout)              \
    X(DestroyPipelineLayout)             \
    X(CreateGraphicsPipelines)           \
    X(CreateComputePipelines)            \
    X(DestroyPipeline)                   \
    X(CreateQueryPool)                   \
    X(DestroyQueryPool)                  \
    X(ResetQueryPool)                    \
    X(GetQueryPoolResults)               \
    X(CreateCommandPool)                 \
    X(DestroyCommandPool)                \
    X(AllocateCommandBuffers)            \
    X(FreeCommandBuffers)                \
    X(BeginCommandBuffer)                \
    X(EndCommandBuffer)                  \
    X(ResetCommandBuffer)                \
    X(CreateFence)                       \
    X(DestroyFence)                      \
    X(ResetFences)                       \
    X(WaitForFences)                     \
    X(CmdPipelineBarrier2)               \
    X(CmdBeginRendering)                 \
    X(CmdEndRendering)                   \
    X(CmdBindPipeline)                   \
    X(CmdPushConstants)                  \
    X(CmdSetViewport)                    \
    X(CmdSetScissor)                     \
    X(CmdSetStencilReference)            \
    X(CmdDraw)                           \
    X(CmdDispatch)                       \
    X(CmdUpdateBuffer)                   \
    X(CmdFillBuffer)                     \
    X(CmdClearColorImage)                \
    X(CmdClearDepthStencilImage)         \
    X(CmdCopyImageToBuffer)              \
    X(CmdBeginQuery)                     \
    X(CmdEndQuery)                       \
    X(CmdResetQueryPool)                 \
    X(CmdWriteTimestamp2)

// Device-level entry points of VK_KHR_push_descriptor.
#define RG_VK_PUSH_DESCRIPTOR_FUNCTIONS(X) X(CmdPushDescriptorSetKHR)

struct VulkanFunctions {
#define RG_VK_MEMBER(name) PFN_vk##name name = nullptr;
    PFN_vkGetInstanceProcAddr GetInstanceProcAddr = nullptr;
    RG_VK_GLOBAL_FUNCTIONS(RG_VK_MEMBER)
    RG_VK_INSTANCE_FUNCTIONS(RG_VK_MEMBER)
    RG_VK_DEBUG_UTILS_FUNCTIONS(RG_VK_MEMBER)
    RG_VK_DEVICE_FUNCTIONS(RG_VK_MEMBER)
    RG_VK_PUSH_DESCRIPTOR_FUNCTIONS(RG_VK_MEMBER)
#undef RG_VK_MEMBER

    // Each throws VulkanError naming the first entry point the source does not give.
    // `getInstanceProcAddr` null: the Vulkan loader's (loaderProcAddr()).
    void loadGlobal(PFN_vkGetInstanceProcAddr getInstanceProcAddr);
    void loadInstance(VkInstance instance);
    void loadDevice(VkDevice device);
};

// The Vulkan loader's vkGetInstanceProcAddr, from libvulkan.so.1 opened at run time (the same
// library when the program links it already). Throws VulkanError when there is none.
PFN_vkGetInstanceProcAddr loaderProcAddr();

}  // namespace rg
