// An engine that links no Vulkan loader, as engines built on volk do: compiled with
// VK_NO_PROTOTYPES, it opens libvulkan.so.1 itself, keeps its entry points in function-pointer
// globals loaded from vkGetInstanceProcAddr and vkGetDeviceProcAddr, and hands the plugin its
// vkGetInstanceProcAddr. It renders one frame under validation (synchronization validation on) and
// checks that light came out; any validation message, refusal or error fails it (exit code 1).
// run_consumer.cmake checks with readelf that the executable does not need libvulkan.
#include <dlfcn.h>

#include <vulkan/vulkan.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>

#ifndef VK_NO_PROTOTYPES
#error "this engine must be compiled with VK_NO_PROTOTYPES: it binds no Vulkan symbol"
#endif

// The engine's entry points, volk's way: globals named as Vulkan's functions.
#define GLOBAL_FUNCTIONS(X) X(vkCreateInstance)
#define INSTANCE_FUNCTIONS(X)                   \
    X(vkDestroyInstance)                        \
    X(vkEnumeratePhysicalDevices)               \
    X(vkGetPhysicalDeviceProperties)            \
    X(vkGetPhysicalDeviceQueueFamilyProperties) \
    X(vkGetPhysicalDeviceMemoryProperties)      \
    X(vkCreateDevice)                           \
    X(vkGetDeviceProcAddr)                      \
    X(vkCreateDebugUtilsMessengerEXT)           \
    X(vkDestroyDebugUtilsMessengerEXT)
#define DEVICE_FUNCTIONS(X)          \
    X(vkDestroyDevice)               \
    X(vkGetDeviceQueue)              \
    X(vkQueueSubmit)                 \
    X(vkCreateImage)                 \
    X(vkDestroyImage)                \
    X(vkGetImageMemoryRequirements)  \
    X(vkCreateBuffer)                \
    X(vkDestroyBuffer)               \
    X(vkGetBufferMemoryRequirements) \
    X(vkAllocateMemory)              \
    X(vkFreeMemory)                  \
    X(vkBindImageMemory)             \
    X(vkBindBufferMemory)            \
    X(vkMapMemory)                   \
    X(vkCreateCommandPool)           \
    X(vkDestroyCommandPool)          \
    X(vkAllocateCommandBuffers)      \
    X(vkBeginCommandBuffer)          \
    X(vkEndCommandBuffer)            \
    X(vkCreateFence)                 \
    X(vkDestroyFence)                \
    X(vkWaitForFences)               \
    X(vkCmdPipelineBarrier2)         \
    X(vkCmdClearColorImage)          \
    X(vkCmdClearDepthStencilImage)   \
    X(vkCmdCopyImageToBuffer)

// Static: an executable's globals named vk* must not be offered to the libraries it opens.
#define DEFINE_POINTER(name) static PFN_##name name = nullptr;
static PFN_vkGetInstanceProcAddr vkGetInstanceProcAddr = nullptr;
GLOBAL_FUNCTIONS(DEFINE_POINTER)
INSTANCE_FUNCTIONS(DEFINE_POINTER)
DEVICE_FUNCTIONS(DEFINE_POINTER)
#undef DEFINE_POINTER

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
    if (!reported(severity, type)) return VK_FALSE;
    std::fprintf(stderr, "[validation] %s\n", data->pMessage ? data->pMessage : "");
    ++gMessages;
    return VK_FALSE;
}

void check(VkResult result, const char* call) {
    if (result != VK_SUCCESS)
        throw std::runtime_error(std::string(call) + " returned " + std::to_string(result));
}
#define VK(call) check((call), #call)

void loadLoader() {
    void* library = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!library) throw std::runtime_error(std::string("dlopen libvulkan.so.1: ") + dlerror());
    vkGetInstanceProcAddr =
        reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(library, "vkGetInstanceProcAddr"));
    if (!vkGetInstanceProcAddr)
        throw std::runtime_error("libvulkan.so.1 has no vkGetInstanceProcAddr");
#define LOAD(name)                                                                     \
    name = reinterpret_cast<PFN_##name>(vkGetInstanceProcAddr(VK_NULL_HANDLE, #name)); \
    if (!name) throw std::runtime_error("no " #name);
    GLOBAL_FUNCTIONS(LOAD)
#undef LOAD
}

void loadInstance(VkInstance instance) {
#define LOAD(name)                                                               \
    name = reinterpret_cast<PFN_##name>(vkGetInstanceProcAddr(instance, #name)); \
    if (!name) throw std::runtime_error("no " #name);
    INSTANCE_FUNCTIONS(LOAD)
#undef LOAD
}

void loadDevice(VkDevice device) {
#define LOAD(name)                                                           \
    name = reinterpret_cast<PFN_##name>(vkGetDeviceProcAddr(device, #name)); \
    if (!name) throw std::runtime_error("no " #name);
    DEVICE_FUNCTIONS(LOAD)
#undef LOAD
}

using Mat4 = std::array<float, 16>;

// A camera at (0, 2.5, 9) looking down -z (a view matrix that is a translation), and a 60-degree
// Vulkan perspective.
Mat4 view() {
    return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -2.5f, -9.0f, 1};
}

Mat4 perspective(float aspect, float nearPlane, float farPlane) {
    const float f = 1.0f / std::tan(30.0f * 3.14159265f / 180.0f);
    Mat4 p{};
    p[0] = f / aspect;
    p[5] = -f;
    p[10] = farPlane / (nearPlane - farPlane);
    p[11] = -1.0f;
    p[14] = farPlane * nearPlane / (nearPlane - farPlane);
    return p;
}

float halfToFloat(uint16_t h) {
    const int exponent = (h >> 10) & 31, mantissa = h & 1023;
    const float sign = (h & 0x8000) ? -1.0f : 1.0f;
    if (exponent == 0) return sign * std::ldexp(static_cast<float>(mantissa), -24);
    if (exponent == 31) return mantissa ? NAN : sign * INFINITY;
    return sign * std::ldexp(static_cast<float>(mantissa + 1024), exponent - 25);
}

struct Memory {
    VkPhysicalDeviceMemoryProperties props{};
    uint32_t type(uint32_t bits, VkMemoryPropertyFlags flags) const {
        for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
            if ((bits & (1u << i)) && (props.memoryTypes[i].propertyFlags & flags) == flags)
                return i;
        throw std::runtime_error("no suitable memory type");
    }
};

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

void pipelineBarrier(VkCommandBuffer cmd, const std::vector<VkImageMemoryBarrier2>& images,
                     const VkMemoryBarrier2* memory = nullptr) {
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = static_cast<uint32_t>(images.size());
    dep.pImageMemoryBarriers = images.data();
    dep.memoryBarrierCount = memory ? 1 : 0;
    dep.pMemoryBarriers = memory;
    vkCmdPipelineBarrier2(cmd, &dep);
}

int run() {
    loadLoader();
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME,
                                VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME};
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = &onMessage;
    const VkValidationFeatureEnableEXT sync =
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT validation{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    validation.enabledValidationFeatureCount = 1;
    validation.pEnabledValidationFeatures = &sync;
    validation.pNext = &messengerInfo;
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "lightscatter volk-style consumer";
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    instanceInfo.pNext = &validation;
    instanceInfo.pApplicationInfo = &app;
    instanceInfo.enabledLayerCount = 1;
    instanceInfo.ppEnabledLayerNames = &layer;
    instanceInfo.enabledExtensionCount = 2;
    instanceInfo.ppEnabledExtensionNames = extensions;
    VkInstance instance;
    VK(vkCreateInstance(&instanceInfo, nullptr, &instance));
    loadInstance(instance);
    VkDebugUtilsMessengerEXT messenger;
    VK(vkCreateDebugUtilsMessengerEXT(instance, &messengerInfo, nullptr, &messenger));

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
    Memory memory;
    vkGetPhysicalDeviceMemoryProperties(physical, &memory.props);

    lightscatter::DeviceFeatures features = lightscatter::requiredDeviceFeatures();
    const std::vector<const char*> deviceExtensions = lightscatter::requiredDeviceExtensions();
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = family;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    deviceInfo.pNext = features.chain();
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.enabledExtensionCount = static_cast<uint32_t>(deviceExtensions.size());
    deviceInfo.ppEnabledExtensionNames = deviceExtensions.data();
    VkDevice device;
    VK(vkCreateDevice(physical, &deviceInfo, nullptr, &device));
    loadDevice(device);
    VkQueue queue;
    vkGetDeviceQueue(device, family, 0, &queue);

    // Black color, and depth at the far plane: everything in the image is the plugin's light.
    const VkExtent2D extent{64, 36};
    auto makeImage = [&](VkFormat format, VkImageUsageFlags usage, VkDeviceMemory& bound) {
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = format;
        info.extent = {extent.width, extent.height, 1};
        info.mipLevels = info.arrayLayers = 1;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.tiling = VK_IMAGE_TILING_OPTIMAL;
        info.usage = usage;
        VkImage image;
        VK(vkCreateImage(device, &info, nullptr, &image));
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(device, image, &req);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex =
            memory.type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        VK(vkAllocateMemory(device, &alloc, nullptr, &bound));
        VK(vkBindImageMemory(device, image, bound, 0));
        return image;
    };
    VkDeviceMemory depthMemory, colorMemory, readbackMemory;
    const VkImage depth =
        makeImage(VK_FORMAT_D32_SFLOAT,
                  VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, depthMemory);
    const VkImage color = makeImage(VK_FORMAT_R16G16B16A16_SFLOAT,
                                    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                    colorMemory);
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
        memory.type(req.memoryTypeBits,
                    VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VK(vkAllocateMemory(device, &alloc, nullptr, &readbackMemory));
    VK(vkBindBufferMemory(device, readback, readbackMemory, 0));

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
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

    // The plugin, on the engine's entry points.
    lightscatter::PluginCreateInfo pluginInfo;
    pluginInfo.context = {instance, physical,         device,        queue,
                          family,   features.chain(), app.apiVersion};
    pluginInfo.getInstanceProcAddr = vkGetInstanceProcAddr;
    auto plugin = std::make_unique<lightscatter::Plugin>(pluginInfo);

    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK(vkBeginCommandBuffer(cmd, &begin));
    const VkImageLayout dst = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    pipelineBarrier(cmd,
                    {barrier(depth, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED, dst),
                     barrier(color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, dst)});
    const VkClearDepthStencilValue far{1.0f, 0};
    const VkClearColorValue black{};
    const VkImageSubresourceRange depthRange{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
    const VkImageSubresourceRange colorRange{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearDepthStencilImage(cmd, depth, dst, &far, 1, &depthRange);
    vkCmdClearColorImage(cmd, color, dst, &black, 1, &colorRange);

    lightscatter::FrameDescription frame;
    frame.depth = {depth, VK_FORMAT_D32_SFLOAT, extent,
                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, dst};
    frame.depth.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    frame.color = {color, VK_FORMAT_R16G16B16A16_SFLOAT, extent,
                   VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                       VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                   dst};
    frame.color.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    frame.camera.view = view();
    frame.camera.projection = perspective(float(extent.width) / float(extent.height), 0.1f, 50.0f);
    frame.light.type = lightscatter::LightType::Spot;
    frame.light.position = {0.0f, 6.0f, 0.0f};
    frame.light.direction = {0.0f, -1.0f, 0.0f};
    frame.light.intensity = {40.0f, 38.0f, 35.0f};
    frame.medium.betaM = {0.03f, 0.03f, 0.03f};
    frame.method = lightscatter::Method::Auto;
    frame.profile = lightscatter::Profile::HighPerformance;
    const uint64_t number = plugin->record(cmd, frame);

    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback, 1, &region);
    VkMemoryBarrier2 toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    toHost.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    pipelineBarrier(cmd, {}, &toHost);
    VK(vkEndCommandBuffer(cmd));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    VK(vkQueueSubmit(queue, 1, &submit, fence));
    VK(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX));

    int failures = 0;
    const lightscatter::FrameReport report = plugin->report(number);
    std::printf("frame %llu: %s, %zu passes, %.3f ms on the GPU\n",
                static_cast<unsigned long long>(report.frame), report.method.c_str(),
                report.passes.size(), report.totalMilliseconds);
    if (!report.timed || report.passes.empty()) {
        std::fprintf(stderr, "the frame's report has no times\n");
        ++failures;
    }
    void* mapped = nullptr;
    VK(vkMapMemory(device, readbackMemory, 0, VK_WHOLE_SIZE, 0, &mapped));
    const auto* halves = static_cast<const uint16_t*>(mapped);
    float brightest = 0.0f;
    for (size_t i = 0; i < size_t{extent.width} * extent.height * 4; ++i) {
        const float v = halfToFloat(halves[i]);
        if (!std::isfinite(v)) {
            std::fprintf(stderr, "non-finite color value at %zu\n", i);
            ++failures;
            break;
        }
        if (i % 4 != 3) brightest = std::max(brightest, v);
    }
    std::printf("brightest shaft value: %g\n", static_cast<double>(brightest));
    if (!(brightest > 0.0f)) {
        std::fprintf(stderr, "no light came out\n");
        ++failures;
    }

    plugin.reset();
    vkDestroyFence(device, fence, nullptr);
    vkDestroyCommandPool(device, pool, nullptr);
    vkDestroyBuffer(device, readback, nullptr);
    vkFreeMemory(device, readbackMemory, nullptr);
    vkDestroyImage(device, depth, nullptr);
    vkFreeMemory(device, depthMemory, nullptr);
    vkDestroyImage(device, color, nullptr);
    vkFreeMemory(device, colorMemory, nullptr);
    vkDestroyDevice(device, nullptr);
    vkDestroyDebugUtilsMessengerEXT(instance, messenger, nullptr);
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
