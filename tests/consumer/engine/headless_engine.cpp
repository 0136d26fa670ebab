// A headless Vulkan 1.3 "engine" written against lightscatter's public header alone, the way an
// engine developer integrates the plugin: its own instance (with the Khronos validation layer and
// synchronization validation), its own device made with the plugin's extensions and features, its
// own images, command buffer, submission and fence. It runs docs/integration.md's example
// (tests/plugin/readme_example.cpp) for two frames, reads each frame's report, and checks that
// light came out. Any validation message, refusal or error fails it (exit code 1).
#include <vulkan/vulkan.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "readme_example.h"

namespace {

int gMessages = 0;

// Counts what the validation layer reports: warnings and errors of the validation and performance
// types, as the project's own device does (rendergraph/device.cpp). General-type messages are
// notes, such as the loader's warning "env var 'VK_INSTANCE_LAYERS' defined and adding layers"
// when a user forces the layer on every process: they say nothing about the engine's calls.
bool reported(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
              VkDebugUtilsMessageTypeFlagsEXT type) {
    return severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT &&
           (type & (VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                    VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT)) != 0;
}

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                         VkDebugUtilsMessageTypeFlagsEXT type,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    if (reported(severity, type)) {
        std::fprintf(stderr, "[validation] %s\n", data->pMessage ? data->pMessage : "");
        ++gMessages;
    }
    return VK_FALSE;
}

void check(VkResult result, const char* call) {
    if (result != VK_SUCCESS)
        throw std::runtime_error(std::string(call) + " returned " + std::to_string(result));
}
#define VK(call) check((call), #call)

using Mat4 = std::array<float, 16>;  // column-major

Mat4 multiply(const Mat4& a, const Mat4& b) {
    Mat4 m{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k) m[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
    return m;
}

// Right-handed view looking from `eye` at `target`.
Mat4 lookAt(std::array<float, 3> eye, std::array<float, 3> target, std::array<float, 3> up) {
    auto sub = [](auto a, auto b) {
        return std::array<float, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    };
    auto cross = [](auto a, auto b) {
        return std::array<float, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                    a[0] * b[1] - a[1] * b[0]};
    };
    auto dot = [](auto a, auto b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    auto normalize = [&](auto a) {
        const float l = std::sqrt(dot(a, a));
        return std::array<float, 3>{a[0] / l, a[1] / l, a[2] / l};
    };
    const auto f = normalize(sub(target, eye));
    const auto s = normalize(cross(f, up));
    const auto u = cross(s, f);
    return {s[0], u[0], -f[0], 0, s[1],         u[1],         -f[1],       0,
            s[2], u[2], -f[2], 0, -dot(s, eye), -dot(u, eye), dot(f, eye), 1};
}

// Vulkan clip space: y down, depth 0 at the near plane, 1 at the far plane.
Mat4 perspective(float fovYDegrees, float aspect, float nearPlane, float farPlane) {
    const float f = 1.0f / std::tan(fovYDegrees * 3.14159265f / 360.0f);
    Mat4 p{};
    p[0] = f / aspect;
    p[5] = -f;
    p[10] = farPlane / (nearPlane - farPlane);
    p[11] = -1.0f;
    p[14] = farPlane * nearPlane / (nearPlane - farPlane);
    return p;
}

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
};

uint32_t memoryType(VkPhysicalDevice physical, uint32_t bits, VkMemoryPropertyFlags flags) {
    VkPhysicalDeviceMemoryProperties props;
    vkGetPhysicalDeviceMemoryProperties(physical, &props);
    for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (props.memoryTypes[i].propertyFlags & flags) == flags) return i;
    throw std::runtime_error("no suitable memory type");
}

Image makeImage(VkPhysicalDevice physical, VkDevice device, VkFormat format, VkExtent2D extent,
                VkImageUsageFlags usage) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    Image img;
    VK(vkCreateImage(device, &info, nullptr, &img.image));
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device, img.image, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex =
        memoryType(physical, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK(vkAllocateMemory(device, &alloc, nullptr, &img.memory));
    VK(vkBindImageMemory(device, img.image, img.memory, 0));
    return img;
}

VkImageMemoryBarrier2 barrier(VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                              VkImageLayout to) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = b.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    b.srcAccessMask = b.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, 1, 0, 1};
    return b;
}

void pipelineBarrier(VkCommandBuffer cmd, const std::vector<VkImageMemoryBarrier2>& barriers) {
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = static_cast<uint32_t>(barriers.size());
    dep.pImageMemoryBarriers = barriers.data();
    vkCmdPipelineBarrier2(cmd, &dep);
}

float halfToFloat(uint16_t h) {
    const int exponent = (h >> 10) & 31, mantissa = h & 1023;
    const float sign = (h & 0x8000) ? -1.0f : 1.0f;
    if (exponent == 0) return sign * std::ldexp(static_cast<float>(mantissa), -24);
    if (exponent == 31) return mantissa ? NAN : sign * INFINITY;
    return sign * std::ldexp(static_cast<float>(mantissa + 1024), exponent - 25);
}

int run() {
    // Instance: validation with synchronization validation, and a messenger that counts.
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* instanceExtensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME,
                                        VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME};
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = &onMessage;
    const VkValidationFeatureEnableEXT sync =
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT validation{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    validation.enabledValidationFeatureCount = 1;
    validation.pEnabledValidationFeatures = &sync;
    validation.pNext = &messengerInfo;
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "lightscatter consumer";
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    instanceInfo.pNext = &validation;
    instanceInfo.pApplicationInfo = &app;
    instanceInfo.enabledLayerCount = 1;
    instanceInfo.ppEnabledLayerNames = &layer;
    instanceInfo.enabledExtensionCount = 2;
    instanceInfo.ppEnabledExtensionNames = instanceExtensions;
    VkInstance instance;
    VK(vkCreateInstance(&instanceInfo, nullptr, &instance));
    auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    VkDebugUtilsMessengerEXT messenger;
    VK(createMessenger(instance, &messengerInfo, nullptr, &messenger));

    // The first Vulkan 1.3 device with a graphics + compute queue that has timestamps (lavapipe in
    // CI).
    uint32_t count = 0;
    VK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> physicals(count);
    VK(vkEnumeratePhysicalDevices(instance, &count, physicals.data()));
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    uint32_t family = 0;
    VkPhysicalDeviceProperties props{};
    for (VkPhysicalDevice pd : physicals) {
        vkGetPhysicalDeviceProperties(pd, &props);
        if (props.apiVersion < VK_API_VERSION_1_3) continue;
        uint32_t n = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, nullptr);
        std::vector<VkQueueFamilyProperties> families(n);
        vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, families.data());
        for (uint32_t i = 0; i < n && !physical; ++i)
            if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) &&
                (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) &&
                families[i].timestampValidBits > 0) {
                physical = pd;
                family = i;
            }
        if (physical) break;
    }
    if (!physical) throw std::runtime_error("no Vulkan 1.3 device");
    std::printf("device: %s\n", props.deviceName);

    // [integration-device]
    // The device: the plugin's extensions and features, plus the engine's own.
    lightscatter::DeviceFeatures features = lightscatter::requiredDeviceFeatures();
    const std::vector<const char*> extensions = lightscatter::requiredDeviceExtensions();
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = family;  // graphics + compute, with timestamps
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    deviceInfo.pNext = features.chain();
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    deviceInfo.ppEnabledExtensionNames = extensions.data();
    VkDevice device;
    VK(vkCreateDevice(physical, &deviceInfo, nullptr, &device));
    VkQueue queue;
    vkGetDeviceQueue(device, family, 0, &queue);

    Engine engine;
    // With the VkApplicationInfo::apiVersion the instance was created with (`app` above), which
    // Vulkan cannot be asked for.
    engine.context = {instance, physical, device, queue, family, features.chain(), app.apiVersion};
    // [integration-device]

    // The engine's images: depth and shadow map cleared to the far value (an empty scene, every
    // point lit), black HDR color.
    const VkExtent2D extent{32, 24};
    const Image depth = makeImage(physical, device, VK_FORMAT_D32_SFLOAT, extent,
                                  VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    const Image color = makeImage(physical, device, VK_FORMAT_R16G16B16A16_SFLOAT, extent,
                                  VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                      VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    const Image shadow = makeImage(physical, device, VK_FORMAT_D32_SFLOAT, {1024, 1024},
                                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);

    VkBufferCreateInfo bufferInfo{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bufferInfo.size = VkDeviceSize{extent.width} * extent.height * 8;
    bufferInfo.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VkBuffer readback;
    VK(vkCreateBuffer(device, &bufferInfo, nullptr, &readback));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, readback, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex =
        memoryType(physical, req.memoryTypeBits,
                   VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VkDeviceMemory readbackMemory;
    VK(vkAllocateMemory(device, &alloc, nullptr, &readbackMemory));
    VK(vkBindBufferMemory(device, readback, readbackMemory, 0));

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = family;
    VkCommandPool pool;
    VK(vkCreateCommandPool(device, &poolInfo, nullptr, &pool));
    VkCommandBufferAllocateInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cmdInfo.commandPool = pool;
    cmdInfo.commandBufferCount = 1;
    VkCommandBuffer cmd;
    VK(vkAllocateCommandBuffers(device, &cmdInfo, &cmd));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    VK(vkCreateFence(device, &fenceInfo, nullptr, &fence));

    engine.commandBuffer = cmd;
    engine.extent = extent;
    engine.depth = depth.image;
    engine.hdrColor = color.image;
    engine.shadowMap = shadow.image;
    engine.view = lookAt({0.0f, 2.5f, 9.0f}, {0.0f, 1.5f, 0.0f}, {0.0f, 1.0f, 0.0f});
    engine.projection = perspective(60.0f, float(extent.width) / float(extent.height), 0.1f, 50.0f);
    engine.lightViewProjection =
        multiply(perspective(64.0f, 1.0f, 0.5f, 30.0f),
                 lookAt({0.0f, 6.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}));

    float brightest = 0.0f;
    int failures = 0;
    for (uint64_t expected = 1; expected <= 2; ++expected) {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        VK(vkBeginCommandBuffer(cmd, &begin));
        // The engine's frame: clear its images, leave them where docs/integration.md's example says
        // they are.
        const VkImageLayout dst = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        pipelineBarrier(
            cmd, {barrier(depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED, dst),
                  barrier(shadow.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED, dst),
                  barrier(color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, dst)});
        const VkClearDepthStencilValue far{1.0f, 0};
        const VkClearColorValue black{};
        VkImageSubresourceRange depthRange{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
        VkImageSubresourceRange colorRange{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearDepthStencilImage(cmd, depth.image, dst, &far, 1, &depthRange);
        vkCmdClearDepthStencilImage(cmd, shadow.image, dst, &far, 1, &depthRange);
        vkCmdClearColorImage(cmd, color.image, dst, &black, 1, &colorRange);
        const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        pipelineBarrier(
            cmd, {barrier(depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, dst, read),
                  barrier(shadow.image, VK_IMAGE_ASPECT_DEPTH_BIT, dst, read),
                  barrier(color.image, VK_IMAGE_ASPECT_COLOR_BIT, dst, VK_IMAGE_LAYOUT_GENERAL)});

        const uint64_t frameNumber = recordLightShafts(engine);

        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {extent.width, extent.height, 1};
        pipelineBarrier(cmd,
                        {barrier(color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL)});
        vkCmdCopyImageToBuffer(cmd, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback, 1,
                               &region);
        VkMemoryBarrier2 toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        toHost.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
        toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
        toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.memoryBarrierCount = 1;
        dep.pMemoryBarriers = &toHost;
        vkCmdPipelineBarrier2(cmd, &dep);
        VK(vkEndCommandBuffer(cmd));

        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmd;
        VK(vkQueueSubmit(queue, 1, &submit, fence));
        VK(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX));
        VK(vkResetFences(device, 1, &fence));

        const lightscatter::FrameReport report = engine.lightShafts->report(frameNumber);
        std::printf("frame %llu: %zu passes, %.3f ms on the GPU\n",
                    static_cast<unsigned long long>(report.frame), report.passes.size(),
                    report.totalMilliseconds);
        if (frameNumber != expected || report.frame != frameNumber || !report.timed ||
            report.passes.empty()) {
            std::fprintf(stderr, "frame %llu: unexpected number or report\n",
                         static_cast<unsigned long long>(expected));
            ++failures;
        }

        void* mapped = nullptr;
        VK(vkMapMemory(device, readbackMemory, 0, VK_WHOLE_SIZE, 0, &mapped));
        const auto* halves = static_cast<const uint16_t*>(mapped);
        for (size_t i = 0; i < size_t{extent.width} * extent.height * 4; ++i) {
            const float v = halfToFloat(halves[i]);
            if (!std::isfinite(v)) {
                std::fprintf(stderr, "non-finite color value at %zu\n", i);
                ++failures;
                break;
            }
            if (i % 4 != 3) brightest = std::max(brightest, v);
        }
        vkUnmapMemory(device, readbackMemory);
    }
    std::printf("brightest shaft value: %g\n", static_cast<double>(brightest));
    if (!(brightest > 0.0f)) {
        std::fprintf(stderr, "no light came out\n");
        ++failures;
    }

    // The plugin goes before the device it works on.
    engine.lightShafts.reset();
    vkDestroyFence(device, fence, nullptr);
    vkDestroyCommandPool(device, pool, nullptr);
    vkDestroyBuffer(device, readback, nullptr);
    vkFreeMemory(device, readbackMemory, nullptr);
    for (const Image& img : {depth, color, shadow}) {
        vkDestroyImage(device, img.image, nullptr);
        vkFreeMemory(device, img.memory, nullptr);
    }
    vkDestroyDevice(device, nullptr);
    destroyMessenger(instance, messenger, nullptr);
    vkDestroyInstance(instance, nullptr);
    if (gMessages > 0) std::fprintf(stderr, "%d validation message(s)\n", gMessages);
    return failures == 0 && gMessages == 0 ? 0 : 1;
}

}  // namespace

int main() {
    try {
        return run();
    } catch (const lightscatter::InvalidInput& e) {
        std::fprintf(stderr, "refused: %s\n", e.what());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
    }
    return 1;
}
