#pragma once
// The engine's vkGetInstanceProcAddr for the plugin (PluginCreateInfo::getInstanceProcAddr): the
// loader's entry points, except for the calls a frame loop needs the plugin not to make while it
// records (waits, submissions) or to make only the first time it meets something (pipelines,
// device memory), which go through wrappers that count them. The plugin asks vkGetDeviceProcAddr,
// found through vkGetInstanceProcAddr, for device-level entry points, so that one is wrapped too.
// Only calls made through these pointers count: the engine's own calls go to the loader it links.
#include <vulkan/vulkan.h>

#include <cstdint>

namespace frame_loop {

struct CallCounts {
    uint64_t deviceWaitIdle = 0;
    uint64_t queueWaitIdle = 0;
    uint64_t waitForFences = 0;
    uint64_t queueSubmit = 0;
    uint64_t queueSubmit2 = 0;
    uint64_t pipelines = 0;       // made by vkCreateGraphicsPipelines and vkCreateComputePipelines
    uint64_t allocations = 0;     // vkAllocateMemory calls that succeeded
    uint64_t allocatedBytes = 0;  // ... and their sizes
    int64_t bytesInUse = 0;       // allocated minus freed (vkFreeMemory)

    uint64_t waits() const { return deviceWaitIdle + queueWaitIdle + waitForFences; }
    uint64_t submits() const { return queueSubmit + queueSubmit2; }
    // What happened between two readings (bytesInUse: the change).
    CallCounts operator-(const CallCounts& before) const;
};

// Everything counted so far, by every thread.
CallCounts callCounts();

// The vkGetInstanceProcAddr to hand the plugin.
VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL countingGetInstanceProcAddr(VkInstance instance,
                                                                     const char* name);

}  // namespace frame_loop
