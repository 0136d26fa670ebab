#include "device_memory.h"

#include <algorithm>
#include <cstdio>

#include "fault_injection.h"
#include "format_info.h"
#include "vk_error.h"

namespace rg {
namespace {

std::string deviceHas(const Device& device, uint32_t memoryType) {
    const VkPhysicalDeviceMemoryProperties& m = device.memoryProperties();
    const uint32_t heap = memoryType < m.memoryTypeCount ? m.memoryTypes[memoryType].heapIndex : 0;
    std::string s = "the device has " + bytesText(m.memoryHeaps[heap].size) + " in heap " +
                    std::to_string(heap);
    if (device.maxAllocationSize() > 0)
        s += ", at most " + bytesText(device.maxAllocationSize()) + " per allocation";
    return s;
}

[[noreturn]] void outOfMemory(const Device& device, VkDeviceSize bytes, uint32_t memoryType,
                              const std::string& what, const std::string& why) {
    throw OutOfDeviceMemory("out of device memory: " + what + " needs " + bytesText(bytes) + "; " +
                            deviceHas(device, memoryType) + " (" + why + ")");
}

// Memory for `req` of a type with `properties`, named for `name` and bound by `bind` (a
// vkBind*Memory call, named `call`); freed again when the bind fails.
template <class Bind>
VkDeviceMemory allocateAndBind(const Device& device, const VkMemoryRequirements& req,
                               VkMemoryPropertyFlags properties, const std::string& name,
                               const std::string& what, const char* call, Bind bind) {
    const uint32_t type = device.findMemoryType(req.memoryTypeBits, properties);
    const VkDeviceMemory memory = allocateDeviceMemory(device, req.size, type, what);
    try {
        device.setName(memory, VK_OBJECT_TYPE_DEVICE_MEMORY, name + " memory");
        checkBind(device, bind(memory), call, req.size, type, what);
    } catch (...) {
        device.vk().FreeMemory(device.device(), memory, device.allocator());
        throw;
    }
    return memory;
}

}  // namespace

std::string bytesText(VkDeviceSize bytes) {
    const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
    double v = static_cast<double>(bytes);
    int u = 0;
    while (v >= 1024.0 && u < 4) {
        v /= 1024.0;
        ++u;
    }
    char buf[32];
    if (u == 0)
        std::snprintf(buf, sizeof buf, "%llu bytes", static_cast<unsigned long long>(bytes));
    else
        std::snprintf(buf, sizeof buf,
                      v == static_cast<double>(static_cast<uint64_t>(v)) ? "%.0f %s" : "%.1f %s", v,
                      units[u]);
    return buf;
}

VkDeviceMemory allocateDeviceMemory(const Device& device, VkDeviceSize bytes, uint32_t memoryType,
                                    const std::string& what) {
    const VkPhysicalDeviceMemoryProperties& m = device.memoryProperties();
    if (memoryType < m.memoryTypeCount) {
        const VkDeviceSize heap = m.memoryHeaps[m.memoryTypes[memoryType].heapIndex].size;
        if (bytes > heap) outOfMemory(device, bytes, memoryType, what, "more than the whole heap");
    }
    if (device.maxAllocationSize() > 0 && bytes > device.maxAllocationSize())
        outOfMemory(device, bytes, memoryType, what, "more than maxMemoryAllocationSize");
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = bytes;
    info.memoryTypeIndex = memoryType;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    const VkResult r =
        detail::creationFails()
            ? VK_ERROR_OUT_OF_DEVICE_MEMORY
            : device.vk().AllocateMemory(device.device(), &info, device.allocator(), &memory);
    if (r == VK_ERROR_OUT_OF_DEVICE_MEMORY || r == VK_ERROR_OUT_OF_HOST_MEMORY)
        outOfMemory(device, bytes, memoryType, what,
                    std::string(resultName(r)) + " from vkAllocateMemory");
    check(r, "vkAllocateMemory");
    return memory;
}

void checkBind(const Device& device, VkResult result, const char* call, VkDeviceSize bytes,
               uint32_t memoryType, const std::string& what) {
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
        outOfMemory(device, bytes, memoryType, what,
                    std::string(resultName(result)) + " from " + call);
    check(result, call);
}

void checkImageLimits(const Device& device, VkExtent2D extent, uint32_t layers,
                      const std::string& what) {
    const VkPhysicalDeviceLimits& l = device.properties().limits;
    if (extent.width > l.maxImageDimension2D || extent.height > l.maxImageDimension2D)
        throw VulkanError(what + " is " + std::to_string(extent.width) + "x" +
                          std::to_string(extent.height) + ": the device takes at most " +
                          std::to_string(l.maxImageDimension2D) +
                          " per side (maxImageDimension2D)");
    if (layers > l.maxImageArrayLayers)
        throw VulkanError(what + " has " + std::to_string(layers) +
                          " layers: the device takes at most " +
                          std::to_string(l.maxImageArrayLayers) + " (maxImageArrayLayers)");
}

void checkImageLimits(const Device& device, const VkImageCreateInfo& info,
                      const std::string& what) {
    const VkExtent3D e = info.extent;
    if (info.imageType != VK_IMAGE_TYPE_3D) {
        checkImageLimits(device, {e.width, e.height}, info.arrayLayers, what);
    } else {
        const uint32_t most = device.properties().limits.maxImageDimension3D;
        if (e.width > most || e.height > most || e.depth > most)
            throw VulkanError(what + " is " + std::to_string(e.width) + "x" +
                              std::to_string(e.height) + "x" + std::to_string(e.depth) +
                              ": the device takes at most " + std::to_string(most) +
                              " per side of a 3D image (maxImageDimension3D)");
    }
    checkImageFormatLimits(device, info, what);
}

void checkImageFormatLimits(const Device& device, const VkImageCreateInfo& info,
                            const std::string& what) {
    const VkExtent3D e = info.extent;
    const std::string image =
        what + " (" + std::to_string(e.width) + "x" + std::to_string(e.height) +
        (e.depth > 1 ? "x" + std::to_string(e.depth) : "") + " " + formatName(info.format) +
        (info.arrayLayers > 1 ? ", " + std::to_string(info.arrayLayers) + " layers" : "") + ")";
    VkImageFormatProperties p{};
    const VkResult r = device.vk().GetPhysicalDeviceImageFormatProperties(
        device.physical(), info.format, info.imageType, info.tiling, info.usage, info.flags, &p);
    if (r == VK_ERROR_FORMAT_NOT_SUPPORTED)
        throw VulkanError(image +
                          ": the device makes no image of this format, type, tiling, usage and "
                          "flags (vkGetPhysicalDeviceImageFormatProperties)");
    if (r != VK_SUCCESS)
        throw VulkanError(image +
                          ": vkGetPhysicalDeviceImageFormatProperties failed: " + resultName(r));
    if (e.width > p.maxExtent.width || e.height > p.maxExtent.height || e.depth > p.maxExtent.depth)
        throw VulkanError(
            image + ": the device takes at most " + std::to_string(p.maxExtent.width) + "x" +
            std::to_string(p.maxExtent.height) + "x" + std::to_string(p.maxExtent.depth) +
            " of this format and usage (vkGetPhysicalDeviceImageFormatProperties)");
    if (info.arrayLayers > p.maxArrayLayers)
        throw VulkanError(image + ": the device takes at most " + std::to_string(p.maxArrayLayers) +
                          " layers of this format and usage "
                          "(vkGetPhysicalDeviceImageFormatProperties)");
    // The size the validation layer weighs against maxResourceSize: texels times their bytes,
    // rounded up to bufferImageGranularity (what a driver really needs is known only once the
    // image exists, and creating an image past the limit is already outside the specification).
    const VkDeviceSize texels =
        VkDeviceSize{e.width} * e.height * e.depth * info.arrayLayers * info.samples;
    const VkDeviceSize granularity =
        std::max<VkDeviceSize>(device.properties().limits.bufferImageGranularity, 1);
    const VkDeviceSize bytes =
        (texels * texelBytes(info.format) + granularity - 1) / granularity * granularity;
    // Exact counts: a limit of 2^32 - 1 bytes and an image of 2^32 both round to 4 GiB.
    if (bytes > p.maxResourceSize)
        throw VulkanError(image + " needs " + std::to_string(bytes) + " bytes (" +
                          bytesText(bytes) + "): the device takes at most " +
                          std::to_string(p.maxResourceSize) +
                          " bytes for one image of this format and usage (maxResourceSize, "
                          "vkGetPhysicalDeviceImageFormatProperties)");
}

BoundBuffer createBoundBuffer(const Device& device, const VkBufferCreateInfo& info,
                              VkMemoryPropertyFlags properties, const std::string& name,
                              const std::string& what) {
    BoundBuffer b;
    RG_VK_CREATE(device.vk().CreateBuffer(device.device(), &info, device.allocator(), &b.buffer));
    try {
        device.setName(b.buffer, VK_OBJECT_TYPE_BUFFER, name);
        VkMemoryRequirements req;
        device.vk().GetBufferMemoryRequirements(device.device(), b.buffer, &req);
        b.memory = allocateAndBind(
            device, req, properties, name, what, "vkBindBufferMemory", [&](VkDeviceMemory m) {
                return device.vk().BindBufferMemory(device.device(), b.buffer, m, 0);
            });
        b.bytes = req.size;
    } catch (...) {
        device.vk().DestroyBuffer(device.device(), b.buffer, device.allocator());
        throw;
    }
    return b;
}

BoundImage createBoundImage(const Device& device, const VkImageCreateInfo& info,
                            VkMemoryPropertyFlags properties, const std::string& name,
                            const std::string& what) {
    BoundImage b;
    RG_VK_CREATE(device.vk().CreateImage(device.device(), &info, device.allocator(), &b.image));
    try {
        device.setName(b.image, VK_OBJECT_TYPE_IMAGE, name);
        VkMemoryRequirements req;
        device.vk().GetImageMemoryRequirements(device.device(), b.image, &req);
        b.memory = allocateAndBind(
            device, req, properties, name, what, "vkBindImageMemory", [&](VkDeviceMemory m) {
                return device.vk().BindImageMemory(device.device(), b.image, m, 0);
            });
        b.bytes = req.size;
    } catch (...) {
        device.vk().DestroyImage(device.device(), b.image, device.allocator());
        throw;
    }
    return b;
}

}  // namespace rg
