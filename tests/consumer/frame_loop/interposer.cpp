#include "interposer.h"

#include <array>
#include <atomic>
#include <cstring>
#include <mutex>
#include <unordered_map>

namespace frame_loop {
namespace {

// The counts are atomics: two plugins may record on two threads at once.
struct AtomicCounts {
    std::atomic<uint64_t> deviceWaitIdle{0}, queueWaitIdle{0}, waitForFences{0};
    std::atomic<uint64_t> queueSubmit{0}, queueSubmit2{0};
    std::atomic<uint64_t> pipelines{0}, allocations{0}, allocatedBytes{0};
    std::atomic<int64_t> bytesInUse{0};
};
AtomicCounts counted;

// vkFreeMemory is given a handle, not a size.
std::mutex sizesMutex;
std::unordered_map<VkDeviceMemory, VkDeviceSize> sizes;

enum Entry {
    DeviceWaitIdle,
    QueueWaitIdle,
    WaitForFences,
    QueueSubmit,
    QueueSubmit2,
    AllocateMemory,
    FreeMemory,
    CreateGraphicsPipelines,
    CreateComputePipelines,
    kEntries
};

// What each wrapper calls: the loader's pointer for the name, as the lookup that handed out the
// wrapper found it (through the instance, or through the device and its layers).
std::array<std::atomic<PFN_vkVoidFunction>, kEntries> next{};

template <typename PFN>
PFN real(Entry e) {
    return reinterpret_cast<PFN>(next[e].load());
}

VKAPI_ATTR VkResult VKAPI_CALL deviceWaitIdle(VkDevice device) {
    ++counted.deviceWaitIdle;
    return real<PFN_vkDeviceWaitIdle>(DeviceWaitIdle)(device);
}

VKAPI_ATTR VkResult VKAPI_CALL queueWaitIdle(VkQueue queue) {
    ++counted.queueWaitIdle;
    return real<PFN_vkQueueWaitIdle>(QueueWaitIdle)(queue);
}

VKAPI_ATTR VkResult VKAPI_CALL waitForFences(VkDevice device, uint32_t count, const VkFence* fences,
                                             VkBool32 all, uint64_t timeout) {
    ++counted.waitForFences;
    return real<PFN_vkWaitForFences>(WaitForFences)(device, count, fences, all, timeout);
}

VKAPI_ATTR VkResult VKAPI_CALL queueSubmit(VkQueue queue, uint32_t count,
                                           const VkSubmitInfo* submits, VkFence fence) {
    ++counted.queueSubmit;
    return real<PFN_vkQueueSubmit>(QueueSubmit)(queue, count, submits, fence);
}

VKAPI_ATTR VkResult VKAPI_CALL queueSubmit2(VkQueue queue, uint32_t count,
                                            const VkSubmitInfo2* submits, VkFence fence) {
    ++counted.queueSubmit2;
    return real<PFN_vkQueueSubmit2>(QueueSubmit2)(queue, count, submits, fence);
}

VKAPI_ATTR VkResult VKAPI_CALL allocateMemory(VkDevice device, const VkMemoryAllocateInfo* info,
                                              const VkAllocationCallbacks* allocator,
                                              VkDeviceMemory* memory) {
    const VkResult r = real<PFN_vkAllocateMemory>(AllocateMemory)(device, info, allocator, memory);
    if (r == VK_SUCCESS) {
        ++counted.allocations;
        counted.allocatedBytes += info->allocationSize;
        counted.bytesInUse += static_cast<int64_t>(info->allocationSize);
        std::lock_guard lock(sizesMutex);
        sizes[*memory] = info->allocationSize;
    }
    return r;
}

VKAPI_ATTR void VKAPI_CALL freeMemory(VkDevice device, VkDeviceMemory memory,
                                      const VkAllocationCallbacks* allocator) {
    if (memory) {
        std::lock_guard lock(sizesMutex);
        const auto found = sizes.find(memory);
        if (found != sizes.end()) {
            counted.bytesInUse -= static_cast<int64_t>(found->second);
            sizes.erase(found);
        }
    }
    real<PFN_vkFreeMemory>(FreeMemory)(device, memory, allocator);
}

VKAPI_ATTR VkResult VKAPI_CALL createGraphicsPipelines(VkDevice device, VkPipelineCache cache,
                                                       uint32_t count,
                                                       const VkGraphicsPipelineCreateInfo* infos,
                                                       const VkAllocationCallbacks* allocator,
                                                       VkPipeline* pipelines) {
    counted.pipelines += count;
    return real<PFN_vkCreateGraphicsPipelines>(CreateGraphicsPipelines)(device, cache, count, infos,
                                                                        allocator, pipelines);
}

VKAPI_ATTR VkResult VKAPI_CALL createComputePipelines(VkDevice device, VkPipelineCache cache,
                                                      uint32_t count,
                                                      const VkComputePipelineCreateInfo* infos,
                                                      const VkAllocationCallbacks* allocator,
                                                      VkPipeline* pipelines) {
    counted.pipelines += count;
    return real<PFN_vkCreateComputePipelines>(CreateComputePipelines)(device, cache, count, infos,
                                                                      allocator, pipelines);
}

struct Wrapper {
    const char* name;
    Entry entry;
    PFN_vkVoidFunction function;
};
const Wrapper kWrappers[] = {
    {"vkDeviceWaitIdle", DeviceWaitIdle, reinterpret_cast<PFN_vkVoidFunction>(&deviceWaitIdle)},
    {"vkQueueWaitIdle", QueueWaitIdle, reinterpret_cast<PFN_vkVoidFunction>(&queueWaitIdle)},
    {"vkWaitForFences", WaitForFences, reinterpret_cast<PFN_vkVoidFunction>(&waitForFences)},
    {"vkQueueSubmit", QueueSubmit, reinterpret_cast<PFN_vkVoidFunction>(&queueSubmit)},
    {"vkQueueSubmit2", QueueSubmit2, reinterpret_cast<PFN_vkVoidFunction>(&queueSubmit2)},
    // The promoted extension's name reaches the same driver entry point.
    {"vkQueueSubmit2KHR", QueueSubmit2, reinterpret_cast<PFN_vkVoidFunction>(&queueSubmit2)},
    {"vkAllocateMemory", AllocateMemory, reinterpret_cast<PFN_vkVoidFunction>(&allocateMemory)},
    {"vkFreeMemory", FreeMemory, reinterpret_cast<PFN_vkVoidFunction>(&freeMemory)},
    {"vkCreateGraphicsPipelines", CreateGraphicsPipelines,
     reinterpret_cast<PFN_vkVoidFunction>(&createGraphicsPipelines)},
    {"vkCreateComputePipelines", CreateComputePipelines,
     reinterpret_cast<PFN_vkVoidFunction>(&createComputePipelines)},
};

// The wrapper for `name` in place of `found`, or `found` itself.
PFN_vkVoidFunction wrapped(const char* name, PFN_vkVoidFunction found) {
    if (!found) return nullptr;
    for (const Wrapper& w : kWrappers)
        if (std::strcmp(name, w.name) == 0) {
            next[w.entry].store(found);
            return w.function;
        }
    return found;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL countingGetDeviceProcAddr(VkDevice device,
                                                                   const char* name) {
    if (std::strcmp(name, "vkGetDeviceProcAddr") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(&countingGetDeviceProcAddr);
    return wrapped(name, vkGetDeviceProcAddr(device, name));
}

}  // namespace

CallCounts CallCounts::operator-(const CallCounts& b) const {
    CallCounts d;
    d.deviceWaitIdle = deviceWaitIdle - b.deviceWaitIdle;
    d.queueWaitIdle = queueWaitIdle - b.queueWaitIdle;
    d.waitForFences = waitForFences - b.waitForFences;
    d.queueSubmit = queueSubmit - b.queueSubmit;
    d.queueSubmit2 = queueSubmit2 - b.queueSubmit2;
    d.pipelines = pipelines - b.pipelines;
    d.allocations = allocations - b.allocations;
    d.allocatedBytes = allocatedBytes - b.allocatedBytes;
    d.bytesInUse = bytesInUse - b.bytesInUse;
    return d;
}

CallCounts callCounts() {
    CallCounts c;
    c.deviceWaitIdle = counted.deviceWaitIdle;
    c.queueWaitIdle = counted.queueWaitIdle;
    c.waitForFences = counted.waitForFences;
    c.queueSubmit = counted.queueSubmit;
    c.queueSubmit2 = counted.queueSubmit2;
    c.pipelines = counted.pipelines;
    c.allocations = counted.allocations;
    c.allocatedBytes = counted.allocatedBytes;
    c.bytesInUse = counted.bytesInUse;
    return c;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL countingGetInstanceProcAddr(VkInstance instance,
                                                                     const char* name) {
    if (std::strcmp(name, "vkGetInstanceProcAddr") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(&countingGetInstanceProcAddr);
    if (std::strcmp(name, "vkGetDeviceProcAddr") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(&countingGetDeviceProcAddr);
    return wrapped(name, vkGetInstanceProcAddr(instance, name));
}

}  // namespace frame_loop
