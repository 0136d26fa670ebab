// An engine's frame loop around lightscatter (issue #24), written against
// <lightscatter/lightscatter.h> alone: its own instance (validation with synchronization
// validation; any message fails), its own device, two views (one Plugin each, both recorded into
// the frame's one command buffer) over F frames in flight (F = 1, 2, 3), 120 frames of the events a
// game has, each twice. The plugin's Vulkan calls go through a vkGetInstanceProcAddr of the
// engine's that counts waits, submissions, pipelines and device memory (interposer.h). It asserts
// that record() never waits nor submits, that only an event's first frame, the first time, builds
// (pipelines, device memory, a graph) and every later frame reuses what it built, that what the
// loop renders is bit for bit what a brand-new plugin renders for the same frame, that frames
// recorded ahead keep their own values, and that two plugins record on two threads at once without
// a validation message. Exit code 0 or 1; the per-event table goes to stdout.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <functional>
#include <latch>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "interposer.h"

namespace {

using frame_loop::CallCounts;
using frame_loop::callCounts;
using Mat4 = std::array<float, 16>;  // column-major
using Vec3 = std::array<float, 3>;

// ---- Failures and validation messages --------------------------------------------------------

std::mutex gLogMutex;
int gMessages = 0;
int gFailures = 0;
std::string gPhase = "setup";  // where the loop is, for the messages
// --driver-handles: the layer's unique handles off, so that the plugin sees the driver's handles
// as engines ship (a destroyed image's handle may come back); two frames in flight only.
bool gDriverHandles = false;
// --no-validation: the instance without the validation layer, for record()'s CPU time as an engine
// ships (the layer checks every command record() records); the loop asserts the rest as always.
bool gNoValidation = false;

void setPhase(std::string phase) {
    std::lock_guard lock(gLogMutex);
    gPhase = std::move(phase);
}

void fail(const std::string& what) {
    std::lock_guard lock(gLogMutex);
    ++gFailures;
    std::fprintf(stderr, "FAILED (%s): %s\n", gPhase.c_str(), what.c_str());
}

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
    std::lock_guard lock(gLogMutex);
    ++gMessages;
    std::fprintf(stderr, "[validation, %s] %s\n", gPhase.c_str(),
                 data->pMessage ? data->pMessage : "");
    return VK_FALSE;
}

void check(VkResult result, const char* call) {
    if (result != VK_SUCCESS)
        throw std::runtime_error(std::string(call) + " returned " + std::to_string(result));
}
#define VK(call) check((call), #call)

// ---- Cameras ---------------------------------------------------------------------------------

Mat4 multiply(const Mat4& a, const Mat4& b) {
    Mat4 m{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k) m[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
    return m;
}

Mat4 lookAt(Vec3 eye, Vec3 target, Vec3 up) {
    auto sub = [](Vec3 a, Vec3 b) { return Vec3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
    auto cross = [](Vec3 a, Vec3 b) {
        return Vec3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                    a[0] * b[1] - a[1] * b[0]};
    };
    auto dot = [](Vec3 a, Vec3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    auto normalize = [&](Vec3 a) {
        const float l = std::sqrt(dot(a, a));
        return Vec3{a[0] / l, a[1] / l, a[2] / l};
    };
    const Vec3 f = normalize(sub(target, eye));
    const Vec3 s = normalize(cross(f, up));
    const Vec3 u = cross(s, f);
    return {s[0], u[0], -f[0], 0, s[1],         u[1],         -f[1],       0,
            s[2], u[2], -f[2], 0, -dot(s, eye), -dot(u, eye), dot(f, eye), 1};
}

// Vulkan clip space: y down, depth 0 at the near plane and 1 at the far plane.
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

// ---- The engine's Vulkan objects -------------------------------------------------------------

struct Gpu {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    PFN_vkDestroyDebugUtilsMessengerEXT destroyMessenger = nullptr;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    uint32_t family = 0;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    lightscatter::DeviceFeatures features;  // the chain the device was created with
    uint32_t apiVersion = 0;                // VkApplicationInfo::apiVersion of the instance
    VkPhysicalDeviceMemoryProperties memory{};

    lightscatter::VulkanContext context() {
        return {instance, physical, device, queue, family, features.chain(), apiVersion};
    }
};

void createGpu(Gpu& g) {
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
    const VkValidationFeatureDisableEXT uniqueHandles =
        VK_VALIDATION_FEATURE_DISABLE_UNIQUE_HANDLES_EXT;
    validation.disabledValidationFeatureCount = gDriverHandles ? 1 : 0;
    validation.pDisabledValidationFeatures = &uniqueHandles;
    validation.pNext = &messengerInfo;
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "lightscatter frame loop";
    app.apiVersion = VK_API_VERSION_1_3;
    g.apiVersion = app.apiVersion;
    VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    instanceInfo.pNext = gNoValidation ? static_cast<const void*>(&messengerInfo) : &validation;
    instanceInfo.pApplicationInfo = &app;
    instanceInfo.enabledLayerCount = gNoValidation ? 0 : 1;
    instanceInfo.ppEnabledLayerNames = &layer;
    instanceInfo.enabledExtensionCount = gNoValidation ? 1 : 2;
    instanceInfo.ppEnabledExtensionNames = extensions;
    VK(vkCreateInstance(&instanceInfo, nullptr, &g.instance));
    auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(g.instance, "vkCreateDebugUtilsMessengerEXT"));
    g.destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(g.instance, "vkDestroyDebugUtilsMessengerEXT"));
    VK(createMessenger(g.instance, &messengerInfo, nullptr, &g.messenger));

    uint32_t count = 0;
    VK(vkEnumeratePhysicalDevices(g.instance, &count, nullptr));
    std::vector<VkPhysicalDevice> physicals(count);
    VK(vkEnumeratePhysicalDevices(g.instance, &count, physicals.data()));
    VkPhysicalDeviceProperties props{};
    for (VkPhysicalDevice pd : physicals) {
        vkGetPhysicalDeviceProperties(pd, &props);
        if (props.apiVersion < VK_API_VERSION_1_3) continue;
        uint32_t n = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, nullptr);
        std::vector<VkQueueFamilyProperties> families(n);
        vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, families.data());
        for (uint32_t i = 0; i < n && !g.physical; ++i)
            if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) &&
                (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) &&
                families[i].timestampValidBits > 0) {
                g.physical = pd;
                g.family = i;
            }
        if (g.physical) break;
    }
    if (!g.physical) throw std::runtime_error("no Vulkan 1.3 device");
    std::printf("device: %s\n", props.deviceName);
    vkGetPhysicalDeviceMemoryProperties(g.physical, &g.memory);

    g.features = lightscatter::requiredDeviceFeatures();
    const std::vector<const char*> deviceExtensions = lightscatter::requiredDeviceExtensions();
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = g.family;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    deviceInfo.pNext = g.features.chain();
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.enabledExtensionCount = static_cast<uint32_t>(deviceExtensions.size());
    deviceInfo.ppEnabledExtensionNames = deviceExtensions.data();
    VK(vkCreateDevice(g.physical, &deviceInfo, nullptr, &g.device));
    vkGetDeviceQueue(g.device, g.family, 0, &g.queue);
}

uint32_t memoryType(const Gpu& g, uint32_t bits, VkMemoryPropertyFlags flags) {
    for (uint32_t i = 0; i < g.memory.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (g.memory.memoryTypes[i].propertyFlags & flags) == flags)
            return i;
    throw std::runtime_error("no suitable memory type");
}

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
};

Image makeImage(const Gpu& g, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    Image img;
    VK(vkCreateImage(g.device, &info, nullptr, &img.image));
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(g.device, img.image, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = memoryType(g, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK(vkAllocateMemory(g.device, &alloc, nullptr, &img.memory));
    VK(vkBindImageMemory(g.device, img.image, img.memory, 0));
    return img;
}

void destroy(const Gpu& g, Image& img) {
    vkDestroyImage(g.device, img.image, nullptr);
    vkFreeMemory(g.device, img.memory, nullptr);
    img = {};
}

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* data = nullptr;  // mapped for its lifetime
};

Buffer makeHostBuffer(const Gpu& g, VkDeviceSize size, VkBufferUsageFlags usage) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    Buffer b;
    VK(vkCreateBuffer(g.device, &info, nullptr, &b.buffer));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(g.device, b.buffer, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex =
        memoryType(g, req.memoryTypeBits,
                   VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VK(vkAllocateMemory(g.device, &alloc, nullptr, &b.memory));
    VK(vkBindBufferMemory(g.device, b.buffer, b.memory, 0));
    VK(vkMapMemory(g.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.data));
    return b;
}

void destroy(const Gpu& g, Buffer& b) {
    vkDestroyBuffer(g.device, b.buffer, nullptr);
    vkFreeMemory(g.device, b.memory, nullptr);
    b = {};
}

// What the engine lets go while frames that use it may still run, destroyed once they are done.
class Graveyard {
  public:
    void bury(uint64_t lastUse, std::function<void()> destroy) {
        items_.push_back({lastUse, std::move(destroy)});
    }
    void collect(uint64_t completed) {
        for (auto it = items_.begin(); it != items_.end();) {
            if (it->first <= completed) {
                it->second();
                it = items_.erase(it);
            } else {
                ++it;
            }
        }
    }
    void collectAll() { collect(UINT64_MAX); }

  private:
    std::vector<std::pair<uint64_t, std::function<void()>>> items_;
};

VkImageMemoryBarrier2 imageBarrier(VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                                   VkImageLayout to, VkPipelineStageFlags2 srcStages,
                                   VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStages,
                                   VkAccessFlags2 dstAccess) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = srcStages;
    b.srcAccessMask = srcAccess;
    b.dstStageMask = dstStages;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, 1, 0, 1};
    return b;
}

void pipelineBarrier(VkCommandBuffer cmd, const std::vector<VkImageMemoryBarrier2>& images,
                     const std::vector<VkMemoryBarrier2>& memory = {}) {
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = static_cast<uint32_t>(images.size());
    dep.pImageMemoryBarriers = images.data();
    dep.memoryBarrierCount = static_cast<uint32_t>(memory.size());
    dep.pMemoryBarriers = memory.data();
    vkCmdPipelineBarrier2(cmd, &dep);
}

// ---- The scene and its events ----------------------------------------------------------------

constexpr VkExtent2D kSmall{160, 90}, kLarge{200, 112};
constexpr uint32_t kShadowMapSize = 256;
constexpr uint32_t kFrames = 120;
constexpr VkFormat kColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkDeviceSize kTexelBytes = 8;
constexpr VkImageUsageFlags kDepthUsage =
    VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
constexpr VkImageUsageFlags kColorUsage =
    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
constexpr float kFogBetaM = 0.02f;  // 1/m

struct Scene {
    bool lightInView = true;
    bool thinMedium = false;  // isotropic and optically thin: auto picks seed 001's closed form
    bool shadow = false;      // the spot's shadow map
    bool large = false;       // kLarge instead of kSmall
    float fogScale = 1.0f;    // Mie scattering kFogBetaM * fogScale
    float g = 0.76f;          // Mie asymmetry
    double timeSeconds = 0.0;

    VkExtent2D extent() const { return large ? kLarge : kSmall; }
};

enum class Kind {
    Start,
    LightLeaves,
    LightReturns,
    MediumThin,
    MediumFog,
    ShadowOn,
    ShadowOff,
    Resize,
    ResizeBack,
    ColorRecreated,
    FogAnimated,
    Count
};
constexpr size_t kKinds = static_cast<size_t>(Kind::Count);

struct KindInfo {
    const char* name;
    const char* method;  // what auto must pick for the occurrence's frames ("none": no chain)
};
const KindInfo kKindInfo[kKinds] = {
    {"start", "epipolar"},
    {"light leaves the views", "none"},
    {"light re-enters", "epipolar"},
    {"medium thin, isotropic", "analytic"},
    {"medium back to fog", "epipolar"},
    {"shadow map on", nullptr},  // the view's (View::shadowedMethod)
    {"shadow map off", "epipolar"},
    {"resize 160x90 -> 200x112", "epipolar"},
    {"resize back to 160x90", "epipolar"},
    {"HDR color recreated", "epipolar"},
    {"fog betaM, g animated", "epipolar"},
};

struct Scheduled {
    uint32_t frame;  // 1-based; the event holds until the next one
    Kind kind;
};
// Each event twice; the second round repeats the first 56 frames later, and the fog animation runs
// from its event to the next one (round two: to the last frame).
constexpr Scheduled kSchedule[] = {
    {1, Kind::Start},           {11, Kind::LightLeaves},     {15, Kind::LightReturns},
    {19, Kind::MediumThin},     {25, Kind::MediumFog},       {29, Kind::ShadowOn},
    {35, Kind::ShadowOff},      {39, Kind::Resize},          {45, Kind::ResizeBack},
    {49, Kind::ColorRecreated}, {53, Kind::FogAnimated},     {67, Kind::LightLeaves},
    {71, Kind::LightReturns},   {75, Kind::MediumThin},      {81, Kind::MediumFog},
    {85, Kind::ShadowOn},       {91, Kind::ShadowOff},       {95, Kind::Resize},
    {101, Kind::ResizeBack},    {105, Kind::ColorRecreated}, {109, Kind::FogAnimated},
};
// Frames whose output is compared with a brand-new plugin's: each event's first frame, in both
// rounds (the second reuses what the first built), and each fog animation's last frame.
bool isCheckpoint(uint32_t frame) {
    if (frame == 66 || frame == kFrames) return true;
    return std::any_of(std::begin(kSchedule), std::end(kSchedule),
                       [&](const Scheduled& s) { return s.frame == frame; });
}

// The shadow map's state when a plugin is handed it: fresh from the engine's upload, or already
// read by the view recorded before (left where that plugin's finalLayout says).
enum class ShadowState { Uploaded, Sampled };

struct View {
    std::string name;
    Vec3 eye, target;
    // View A's profile makes auto march a shadowed light per pixel at 160x90, view B's sample it
    // epipolarly (method_choice.cpp: fewer pixels than slices x samples / 24).
    lightscatter::Profile profile = lightscatter::Profile::HighPerformance;
    const char* shadowedMethod = "brute-force";
    VkExtent2D extent{};
    Image depth, color;
    std::unique_ptr<lightscatter::Plugin> plugin;
};

const char* expectedMethod(Kind kind, const View& v) {
    return kind == Kind::ShadowOn ? v.shadowedMethod : kKindInfo[static_cast<size_t>(kind)].method;
}

Mat4 lightViewProjection() {
    return multiply(perspective(64.0f, 1.0f, 0.5f, 30.0f),
                    lookAt({0.0f, 6.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}));
}

lightscatter::FrameDescription describe(const View& v, const Scene& s, VkImage shadowMap,
                                        ShadowState shadowState) {
    lightscatter::FrameDescription f;
    // The engine's last use of depth and color was its own upload and clear (transfer writes);
    // it reads the color back with a copy afterwards.
    f.depth = {v.depth.image, VK_FORMAT_D32_SFLOAT, v.extent, kDepthUsage,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
    f.depth.stages = VK_PIPELINE_STAGE_2_COPY_BIT;
    f.depth.access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    f.depth.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    f.color = {v.color.image, kColorFormat, v.extent, kColorUsage,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
    f.color.stages = VK_PIPELINE_STAGE_2_CLEAR_BIT;
    f.color.access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    f.color.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    f.color.finalStages = VK_PIPELINE_STAGE_2_COPY_BIT;
    f.color.finalAccess = VK_ACCESS_2_TRANSFER_READ_BIT;

    f.camera.view = lookAt(v.eye, v.target, {0.0f, 1.0f, 0.0f});
    f.camera.projection =
        perspective(60.0f, float(v.extent.width) / float(v.extent.height), 0.1f, 50.0f);

    lightscatter::Light& l = f.light;
    l.type = lightscatter::LightType::Spot;
    if (s.lightInView) {
        l.position = {0.0f, 6.0f, 0.0f};
        l.direction = {0.0f, -1.0f, 0.0f};
    } else {
        // Behind both cameras, pointing away, with a range that keeps its cone there.
        l.position = {0.0f, 3.0f, 15.0f};
        l.direction = {0.0f, 0.0f, 1.0f};
        l.range = 5.0f;
    }
    l.intensity = {40.0f, 38.0f, 35.0f};
    l.innerConeAngleDegrees = l.outerConeAngleDegrees = 30.0f;
    l.shadowViewProjection = lightViewProjection();
    if (s.shadow) {
        l.shadowMapSize = kShadowMapSize;
        lightscatter::ImageInput map{shadowMap,
                                     VK_FORMAT_D32_SFLOAT,
                                     {kShadowMapSize, kShadowMapSize},
                                     kDepthUsage,
                                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
        map.stages = VK_PIPELINE_STAGE_2_COPY_BIT;
        map.access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        if (shadowState == ShadowState::Sampled) {
            map.layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
            map.stages =
                VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
            map.access = VK_ACCESS_2_NONE;  // reads: nothing to make available
        }
        map.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        // The next user is the other view's plugin, which samples it.
        map.finalStages =
            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
        map.finalAccess = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
        f.shadowMap = map;
    }

    if (s.thinMedium) {
        f.medium.betaR = {0.0f, 0.0f, 0.0f};
        f.medium.betaM = {5e-4f, 5e-4f, 5e-4f};  // optical depth 0.005 to the light
        f.medium.phase = lightscatter::MiePhase::Isotropic;
    } else {
        const float b = kFogBetaM * s.fogScale;
        f.medium.betaM = {b, b, b};
        f.medium.g = s.g;
    }
    f.timeSeconds = s.timeSeconds;
    f.method = lightscatter::Method::Auto;
    f.profile = v.profile;
    return f;
}

// ---- The engine ------------------------------------------------------------------------------

float halfToFloat(uint16_t h) {
    const int exponent = (h >> 10) & 31, mantissa = h & 1023;
    const float sign = (h & 0x8000) ? -1.0f : 1.0f;
    if (exponent == 0) return sign * std::ldexp(static_cast<float>(mantissa), -24);
    if (exponent == 31) return mantissa ? NAN : sign * INFINITY;
    return sign * std::ldexp(static_cast<float>(mantissa + 1024), exponent - 25);
}

uint32_t extentKey(VkExtent2D e) {
    return e.width << 16 | e.height;
}

struct Engine {
    Gpu gpu;
    Image shadowMap;
    Buffer shadowPattern;
    std::map<uint32_t, Buffer> depthPatterns;  // by extentKey, never rewritten
    std::array<Buffer, 3> readbacks;           // kLarge color images
    // The brand-new plugins' images, apart from the loop's so that a comparison takes nothing
    // from the frames in flight: depth and color by extentKey, and a shadow map.
    std::map<uint32_t, std::pair<Image, Image>> referenceImages;
    Image referenceShadowMap;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer oneShot = VK_NULL_HANDLE;
    VkFence oneShotFence = VK_NULL_HANDLE;
    Graveyard graveyard;

    void create() {
        createGpu(gpu);
        shadowMap =
            makeImage(gpu, VK_FORMAT_D32_SFLOAT, {kShadowMapSize, kShadowMapSize}, kDepthUsage);
        referenceShadowMap =
            makeImage(gpu, VK_FORMAT_D32_SFLOAT, {kShadowMapSize, kShadowMapSize}, kDepthUsage);
        // A square occluder and a bar across the cone, the rest at the far plane.
        shadowPattern = makeHostBuffer(gpu, VkDeviceSize{kShadowMapSize} * kShadowMapSize * 4,
                                       VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        auto* texels = static_cast<float*>(shadowPattern.data);
        for (uint32_t y = 0; y < kShadowMapSize; ++y)
            for (uint32_t x = 0; x < kShadowMapSize; ++x) {
                const float u = (float(x) + 0.5f) / float(kShadowMapSize);
                const float v = (float(y) + 0.5f) / float(kShadowMapSize);
                const bool square = u > 0.4f && u < 0.6f && v > 0.4f && v < 0.6f;
                const bool bar = v > 0.25f && v < 0.3f;
                texels[y * kShadowMapSize + x] = square ? 0.6f : bar ? 0.8f : 1.0f;
            }
        for (Buffer& b : readbacks) b = makeReadback();
        VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        poolInfo.queueFamilyIndex = gpu.family;
        VK(vkCreateCommandPool(gpu.device, &poolInfo, nullptr, &pool));
        oneShot = allocateCommandBuffers(pool, 1)[0];
        oneShotFence = createFence(false);
    }

    void destroyAll() {
        VK(vkDeviceWaitIdle(gpu.device));
        graveyard.collectAll();
        vkDestroyFence(gpu.device, oneShotFence, nullptr);
        vkDestroyCommandPool(gpu.device, pool, nullptr);
        for (Buffer& b : readbacks) destroy(gpu, b);
        for (auto& [key, b] : depthPatterns) destroy(gpu, b);
        for (auto& [key, images] : referenceImages) {
            destroy(gpu, images.first);
            destroy(gpu, images.second);
        }
        destroy(gpu, shadowPattern);
        destroy(gpu, shadowMap);
        destroy(gpu, referenceShadowMap);
        vkDestroyDevice(gpu.device, nullptr);
        gpu.destroyMessenger(gpu.instance, gpu.messenger, nullptr);
        vkDestroyInstance(gpu.instance, nullptr);
    }

    Buffer makeReadback() {
        return makeHostBuffer(gpu, VkDeviceSize{kLarge.width} * kLarge.height * kTexelBytes,
                              VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    }

    std::vector<VkCommandBuffer> allocateCommandBuffers(VkCommandPool from, uint32_t count) {
        VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        info.commandPool = from;
        info.commandBufferCount = count;
        std::vector<VkCommandBuffer> cmds(count);
        VK(vkAllocateCommandBuffers(gpu.device, &info, cmds.data()));
        return cmds;
    }

    VkFence createFence(bool signalled) {
        VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        if (signalled) info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        VkFence fence;
        VK(vkCreateFence(gpu.device, &info, nullptr, &fence));
        return fence;
    }

    // The engine's depth: sky in the upper part, a floor that nears the camera downwards and a
    // box, in depth values of the views' projection (near 0.1 m, far 50 m).
    const Buffer& depthPattern(VkExtent2D e) {
        const uint32_t key = extentKey(e);
        auto found = depthPatterns.find(key);
        if (found != depthPatterns.end()) return found->second;
        Buffer b = makeHostBuffer(gpu, VkDeviceSize{e.width} * e.height * 4,
                                  VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        auto* texels = static_cast<float*>(b.data);
        for (uint32_t y = 0; y < e.height; ++y)
            for (uint32_t x = 0; x < e.width; ++x) {
                const float u = (float(x) + 0.5f) / float(e.width);
                const float v = (float(y) + 0.5f) / float(e.height);
                float d = v < 0.45f ? 1.0f : 0.999f - 0.03f * (v - 0.45f);
                if (u > 0.35f && u < 0.55f && v > 0.3f && v < 0.8f) d = 0.985f;
                texels[y * e.width + x] = d;
            }
        return depthPatterns.emplace(key, b).first->second;
    }

    void makeViewImages(View& v, VkExtent2D e) {
        v.extent = e;
        v.depth = makeImage(gpu, VK_FORMAT_D32_SFLOAT, e, kDepthUsage);
        v.color = makeImage(gpu, kColorFormat, e, kColorUsage);
    }

    // The views' images go once the frames up to `lastUse` are done.
    void buryViewImages(View& v, uint64_t lastUse, bool depthToo) {
        Image color = v.color;
        graveyard.bury(lastUse, [this, color]() mutable { destroy(gpu, color); });
        v.color = {};
        if (depthToo) {
            Image depth = v.depth;
            graveyard.bury(lastUse, [this, depth]() mutable { destroy(gpu, depth); });
            v.depth = {};
        }
    }

    // The engine's own work before the plugins: each view's depth uploaded and color cleared, the
    // shadow map rendered (uploaded). Everything starts from UNDEFINED: last frame's contents are
    // not wanted; the barriers wait on whatever last frame did to the images.
    void recordScene(VkCommandBuffer cmd, const std::vector<const View*>& views,
                     const Image* shadow) {
        const VkImageLayout dst = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        const VkPipelineStageFlags2 all = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        const VkAccessFlags2 written = VK_ACCESS_2_MEMORY_WRITE_BIT;
        const VkPipelineStageFlags2 transfer =
            VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT;
        std::vector<VkImageMemoryBarrier2> barriers;
        for (const View* v : views) {
            barriers.push_back(imageBarrier(v->depth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                                            VK_IMAGE_LAYOUT_UNDEFINED, dst, all, written, transfer,
                                            VK_ACCESS_2_TRANSFER_WRITE_BIT));
            barriers.push_back(imageBarrier(v->color.image, VK_IMAGE_ASPECT_COLOR_BIT,
                                            VK_IMAGE_LAYOUT_UNDEFINED, dst, all, written, transfer,
                                            VK_ACCESS_2_TRANSFER_WRITE_BIT));
        }
        if (shadow)
            barriers.push_back(imageBarrier(shadow->image, VK_IMAGE_ASPECT_DEPTH_BIT,
                                            VK_IMAGE_LAYOUT_UNDEFINED, dst, all, written, transfer,
                                            VK_ACCESS_2_TRANSFER_WRITE_BIT));
        pipelineBarrier(cmd, barriers);
        const VkClearColorValue background{{0.25f, 0.3f, 0.35f, 1.0f}};
        const VkImageSubresourceRange colorRange{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        for (const View* v : views) {
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
            region.imageExtent = {v->extent.width, v->extent.height, 1};
            vkCmdCopyBufferToImage(cmd, depthPattern(v->extent).buffer, v->depth.image, dst, 1,
                                   &region);
            vkCmdClearColorImage(cmd, v->color.image, dst, &background, 1, &colorRange);
        }
        if (shadow) {
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
            region.imageExtent = {kShadowMapSize, kShadowMapSize, 1};
            vkCmdCopyBufferToImage(cmd, shadowPattern.buffer, shadow->image, dst, 1, &region);
        }
    }

    // After a plugin: the view's color (left in TRANSFER_SRC for a copy) into a readback buffer.
    void recordReadback(VkCommandBuffer cmd, const View& v, const Buffer& to) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {v.extent.width, v.extent.height, 1};
        vkCmdCopyImageToBuffer(cmd, v.color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.buffer,
                               1, &region);
        VkMemoryBarrier2 toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        toHost.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
        toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
        toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
        pipelineBarrier(cmd, {}, {toHost});
    }

    static std::vector<uint16_t> read(const Buffer& b, VkExtent2D e) {
        const auto* halves = static_cast<const uint16_t*>(b.data);
        return {halves, halves + size_t{e.width} * e.height * 4};
    }

    void submit(const std::vector<VkCommandBuffer>& cmds, VkFence fence) {
        VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        info.commandBufferCount = static_cast<uint32_t>(cmds.size());
        info.pCommandBuffers = cmds.data();
        VK(vkQueueSubmit(gpu.queue, 1, &info, fence));
    }

    static void begin(VkCommandBuffer cmd) {
        VK(vkResetCommandBuffer(cmd, 0));
        VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        VK(vkBeginCommandBuffer(cmd, &info));
    }

    // The view's frame as a brand-new plugin renders it, on images of its own (the same contents,
    // extent and layouts as the loop's); its calls go straight to the loader, which it opens
    // itself. The reference for the loop's plugins.
    std::vector<uint16_t> renderFresh(const View& v, VkExtent2D extent, const Scene& s,
                                      ShadowState shadowState) {
        auto found = referenceImages.find(extentKey(extent));
        if (found == referenceImages.end())
            found =
                referenceImages
                    .emplace(extentKey(extent),
                             std::pair{makeImage(gpu, VK_FORMAT_D32_SFLOAT, extent, kDepthUsage),
                                       makeImage(gpu, kColorFormat, extent, kColorUsage)})
                    .first;
        View reference;
        reference.eye = v.eye;
        reference.target = v.target;
        reference.profile = v.profile;
        reference.extent = extent;
        reference.depth = found->second.first;
        reference.color = found->second.second;
        lightscatter::PluginCreateInfo info;
        info.framesInFlight = 1;
        info.context = gpu.context();
        lightscatter::Plugin fresh(info);
        begin(oneShot);
        recordScene(oneShot, {&reference}, s.shadow ? &referenceShadowMap : nullptr);
        if (s.shadow && shadowState == ShadowState::Sampled)
            // Where the view recorded before this one leaves it in the loop.
            pipelineBarrier(
                oneShot, {imageBarrier(referenceShadowMap.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                       VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                       VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT)});
        fresh.record(oneShot, describe(reference, s, referenceShadowMap.image, shadowState));
        recordReadback(oneShot, reference, readbacks[2]);
        VK(vkEndCommandBuffer(oneShot));
        submit({oneShot}, oneShotFence);
        VK(vkWaitForFences(gpu.device, 1, &oneShotFence, VK_TRUE, UINT64_MAX));
        VK(vkResetFences(gpu.device, 1, &oneShotFence));
        return read(readbacks[2], extent);
    }
};

// Bit for bit, or the differences named.
bool compareImages(const std::string& what, const std::vector<uint16_t>& loop,
                   const std::vector<uint16_t>& fresh, VkExtent2D e) {
    size_t differing = 0;
    float worst = 0.0f;
    size_t first = SIZE_MAX;
    for (size_t i = 0; i < loop.size(); ++i)
        if (loop[i] != fresh[i]) {
            ++differing;
            if (first == SIZE_MAX) first = i;
            worst = std::max(worst, std::fabs(halfToFloat(loop[i]) - halfToFloat(fresh[i])));
        }
    if (differing == 0) return true;
    const size_t texel = first / 4;
    fail(what + ": " + std::to_string(differing) + " of " + std::to_string(loop.size()) +
         " channels differ from a brand-new plugin's render (largest difference " +
         std::to_string(worst) + "; first at pixel " + std::to_string(texel % e.width) + "," +
         std::to_string(texel / e.width) + " channel " + std::to_string(first % 4) + ": " +
         std::to_string(halfToFloat(loop[first])) + " against " +
         std::to_string(halfToFloat(fresh[first])) + ")");
    return false;
}

// ---- The frame loop --------------------------------------------------------------------------

struct FrameStats {
    Kind kind = Kind::Start;
    int occurrence = 0;            // 1: the event's first, 2: its second
    bool eventFrame = false;       // the occurrence's first frame
    CallCounts calls;              // the plugins' calls inside record()
    std::vector<double> recordMs;  // one per view
    uint32_t graphsCompiled = 0;   // FrameReport::graphCompiled, both views
    std::set<std::string> methods;
    int64_t bytesInUse = 0;  // the plugins' device memory after the frame's record() calls
};

struct RunResult {
    uint32_t framesInFlight = 0;
    std::vector<FrameStats> frames;  // by frame - 1
    CallCounts construction;         // the two plugins' constructors
    int checkpointsCompared = 0, checkpointsIdentical = 0;
    double seconds = 0;
};

struct Slot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    uint32_t frame = 0;                 // the loop's frame it holds, 0: none
    std::array<uint64_t, 2> numbers{};  // record()'s numbers, per view
    // A checkpoint: the frame copies each view's color here, and once its fence has signalled
    // the engine compares them with brand-new plugins' renders of `scene`.
    bool checkpoint = false;
    Scene scene;
    std::array<Buffer, 2> readbacks;
};

std::string describeCounts(const CallCounts& c) {
    return std::to_string(c.deviceWaitIdle) + " vkDeviceWaitIdle, " +
           std::to_string(c.queueWaitIdle) + " vkQueueWaitIdle, " +
           std::to_string(c.waitForFences) + " vkWaitForFences, " + std::to_string(c.queueSubmit) +
           " vkQueueSubmit, " + std::to_string(c.queueSubmit2) + " vkQueueSubmit2";
}

RunResult runFrameLoop(Engine& e, std::array<View, 2>& views, uint32_t framesInFlight) {
    const auto started = std::chrono::steady_clock::now();
    RunResult result;
    result.framesInFlight = framesInFlight;
    result.frames.resize(kFrames);
    Gpu& g = e.gpu;

    const CallCounts beforeCreation = callCounts();
    for (View& v : views) {
        lightscatter::PluginCreateInfo info;
        info.framesInFlight = framesInFlight;
        info.context = g.context();
        info.getInstanceProcAddr = &frame_loop::countingGetInstanceProcAddr;
        v.plugin = std::make_unique<lightscatter::Plugin>(info);
    }
    result.construction = callCounts() - beforeCreation;

    std::vector<Slot> slots(framesInFlight);
    const std::vector<VkCommandBuffer> cmds = e.allocateCommandBuffers(e.pool, framesInFlight);
    for (uint32_t i = 0; i < framesInFlight; ++i) {
        slots[i].cmd = cmds[i];
        slots[i].fence = e.createFence(false);
        for (Buffer& b : slots[i].readbacks) b = e.makeReadback();
    }

    // What the engine learns once a frame's fence has signalled: the plugins' reports.
    auto completed = [&](Slot& slot) {
        if (slot.frame == 0) return;
        FrameStats& stats = result.frames[slot.frame - 1];
        for (size_t i = 0; i < views.size(); ++i) {
            const CallCounts before = callCounts();
            const lightscatter::FrameReport r = views[i].plugin->report(slot.numbers[i]);
            const CallCounts calls = callCounts() - before;
            // report() reads what is there: it never waits either.
            if (calls.waits() != 0 || calls.submits() != 0)
                fail(views[i].name + ": report() called " + describeCounts(calls));
            if (!r.timed)
                fail(views[i].name + " frame " + std::to_string(slot.frame) +
                     ": report() is not timed after the frame's fence signalled");
            stats.graphsCompiled += r.graphCompiled ? 1 : 0;
            stats.methods.insert(r.method);
            const char* expected = expectedMethod(stats.kind, views[i]);
            if (r.method != expected)
                fail(views[i].name + " frame " + std::to_string(slot.frame) + ": auto ran " +
                     r.method + ", the scene asks for " + expected + " (" + r.reason + ")");
        }
        if (slot.checkpoint) {
            // The loop goes on meanwhile: its other frames stay in flight.
            for (size_t i = 0; i < views.size(); ++i) {
                const std::string what = "F=" + std::to_string(framesInFlight) + ", " +
                                         views[i].name + ", frame " + std::to_string(slot.frame);
                setPhase(what + ", a brand-new plugin's render");
                const VkExtent2D extent = slot.scene.extent();
                const std::vector<uint16_t> fresh =
                    e.renderFresh(views[i], extent, slot.scene,
                                  i == 0 ? ShadowState::Uploaded : ShadowState::Sampled);
                ++result.checkpointsCompared;
                if (compareImages(what, Engine::read(slot.readbacks[i], extent), fresh, extent))
                    ++result.checkpointsIdentical;
            }
            slot.checkpoint = false;
        }
        e.graveyard.collect(slot.frame);
        slot.frame = 0;
    };

    Scene scene;
    std::array<int, kKinds> occurrences{};
    Kind kind = Kind::Start;
    int occurrence = 0;
    size_t next = 0;
    for (uint32_t frame = 1; frame <= kFrames; ++frame) {
        Slot& slot = slots[(frame - 1) % framesInFlight];
        // Frame `frame - framesInFlight` used this slot: the plugins are promised it is done.
        if (slot.frame != 0) {
            VK(vkWaitForFences(g.device, 1, &slot.fence, VK_TRUE, UINT64_MAX));
            VK(vkResetFences(g.device, 1, &slot.fence));
            completed(slot);
        }

        // The game's events.
        const bool eventFrame = next < std::size(kSchedule) && kSchedule[next].frame == frame;
        if (eventFrame) {
            kind = kSchedule[next++].kind;
            occurrence = ++occurrences[static_cast<size_t>(kind)];
            switch (kind) {
                case Kind::Start:
                    break;
                case Kind::LightLeaves:
                    scene.lightInView = false;
                    break;
                case Kind::LightReturns:
                    scene.lightInView = true;
                    break;
                case Kind::MediumThin:
                    scene.thinMedium = true;
                    break;
                case Kind::MediumFog:
                    scene.thinMedium = false;
                    scene.fogScale = 1.0f;
                    scene.g = 0.76f;
                    break;
                case Kind::ShadowOn:
                    scene.shadow = true;
                    break;
                case Kind::ShadowOff:
                    scene.shadow = false;
                    break;
                case Kind::Resize:
                case Kind::ResizeBack:
                    scene.large = kind == Kind::Resize;
                    for (View& v : views) {
                        e.buryViewImages(v, frame - 1, true);
                        e.makeViewImages(v, scene.extent());
                    }
                    break;
                case Kind::ColorRecreated:
                    for (View& v : views) {
                        e.buryViewImages(v, frame - 1, false);
                        v.color = makeImage(g, kColorFormat, v.extent, kColorUsage);
                    }
                    break;
                case Kind::FogAnimated:
                case Kind::Count:
                    break;
            }
        }
        if (kind == Kind::FogAnimated) {
            const float t = float(frame);
            scene.fogScale = 1.0f + 0.5f * std::sin(0.35f * t);
            scene.g = 0.6f + 0.2f * std::sin(0.23f * t);
        }
        scene.timeSeconds = frame / 60.0;
        setPhase("F=" + std::to_string(framesInFlight) + ", frame " + std::to_string(frame) + ", " +
                 kKindInfo[static_cast<size_t>(kind)].name + " #" + std::to_string(occurrence));

        FrameStats& stats = result.frames[frame - 1];
        stats.kind = kind;
        stats.occurrence = occurrence;
        stats.eventFrame = eventFrame;
        // Only an event's first frame, the first time, may build: what it builds is kept.
        const bool mayBuild = occurrence == 1 && eventFrame;
        Engine::begin(slot.cmd);
        e.recordScene(slot.cmd, {&views[0], &views[1]}, scene.shadow ? &e.shadowMap : nullptr);
        for (size_t i = 0; i < views.size(); ++i) {
            const lightscatter::FrameDescription description =
                describe(views[i], scene, e.shadowMap.image,
                         i == 0 ? ShadowState::Uploaded : ShadowState::Sampled);
            const CallCounts before = callCounts();
            const auto t0 = std::chrono::steady_clock::now();
            slot.numbers[i] = views[i].plugin->record(slot.cmd, description);
            const auto t1 = std::chrono::steady_clock::now();
            const CallCounts calls = callCounts() - before;
            stats.recordMs.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
            stats.calls.deviceWaitIdle += calls.deviceWaitIdle;
            stats.calls.queueWaitIdle += calls.queueWaitIdle;
            stats.calls.waitForFences += calls.waitForFences;
            stats.calls.queueSubmit += calls.queueSubmit;
            stats.calls.queueSubmit2 += calls.queueSubmit2;
            stats.calls.pipelines += calls.pipelines;
            stats.calls.allocations += calls.allocations;
            stats.calls.allocatedBytes += calls.allocatedBytes;
            if (slot.numbers[i] != frame)
                fail(views[i].name + ": record() numbered frame " + std::to_string(frame) + " " +
                     std::to_string(slot.numbers[i]));
            // The assertions of issue #24: a frame loop's record() never waits for the GPU nor
            // submits, from the first frame on.
            if (calls.waits() != 0 || calls.submits() != 0)
                fail(views[i].name + ": record() called " + describeCounts(calls));
            if (!mayBuild && (calls.pipelines != 0 || calls.allocations != 0))
                fail(views[i].name + ": record() created " + std::to_string(calls.pipelines) +
                     " pipeline(s) and allocated " + std::to_string(calls.allocations) +
                     " block(s) of device memory (" + std::to_string(calls.allocatedBytes) +
                     " bytes) after the event's first frame the first time");
        }
        stats.bytesInUse = callCounts().bytesInUse;
        slot.checkpoint = isCheckpoint(frame);
        slot.scene = scene;
        if (slot.checkpoint)
            for (size_t i = 0; i < views.size(); ++i)
                e.recordReadback(slot.cmd, views[i], slot.readbacks[i]);
        VK(vkEndCommandBuffer(slot.cmd));
        e.submit({slot.cmd}, slot.fence);
        slot.frame = frame;
    }
    // The last frames, in the order they were recorded.
    for (uint32_t frame = kFrames + 1; frame <= kFrames + framesInFlight; ++frame) {
        Slot& slot = slots[(frame - 1) % framesInFlight];
        VK(vkWaitForFences(g.device, 1, &slot.fence, VK_TRUE, UINT64_MAX));
        completed(slot);
    }
    for (Slot& slot : slots) {
        vkDestroyFence(g.device, slot.fence, nullptr);
        for (Buffer& b : slot.readbacks) destroy(g, b);
    }
    vkFreeCommandBuffers(g.device, e.pool, framesInFlight, cmds.data());
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

// Two frames recorded before either is submitted, then submitted in order: each must be its own
// scene's render. Needs two frames in flight.
void runRecordAhead(Engine& e, View& view, const std::string& what, const Scene (&scenes)[2]) {
    setPhase("recording ahead, " + view.name + ", " + what);
    Gpu& g = e.gpu;
    const std::vector<VkCommandBuffer> cmds = e.allocateCommandBuffers(e.pool, 2);
    uint64_t numbers[2] = {};
    for (int i = 0; i < 2; ++i) {
        Engine::begin(cmds[i]);
        e.recordScene(cmds[i], {&view}, scenes[i].shadow ? &e.shadowMap : nullptr);
        const CallCounts before = callCounts();
        numbers[i] = view.plugin->record(
            cmds[i], describe(view, scenes[i], e.shadowMap.image, ShadowState::Uploaded));
        const CallCounts calls = callCounts() - before;
        if (calls.waits() != 0 || calls.submits() != 0)
            fail("record() of a frame recorded ahead called " + describeCounts(calls));
        e.recordReadback(cmds[i], view, e.readbacks[i]);
        VK(vkEndCommandBuffer(cmds[i]));
    }
    e.submit({cmds[0]}, VK_NULL_HANDLE);
    e.submit({cmds[1]}, e.oneShotFence);
    VK(vkWaitForFences(g.device, 1, &e.oneShotFence, VK_TRUE, UINT64_MAX));
    VK(vkResetFences(g.device, 1, &e.oneShotFence));
    std::vector<uint16_t> loop[2];
    for (int i = 0; i < 2; ++i) {
        loop[i] = Engine::read(e.readbacks[i], view.extent);
        if (!view.plugin->report(numbers[i]).timed)
            fail("a frame recorded ahead is not timed once done");
    }
    int identical = 0;
    for (int i = 0; i < 2; ++i)
        identical += compareImages(
            "frame " + std::to_string(i + 1) + " of 2 recorded ahead", loop[i],
            e.renderFresh(view, view.extent, scenes[i], ShadowState::Uploaded), view.extent);
    if (loop[0] == loop[1]) fail("the two frames recorded ahead rendered the same image");
    std::printf("recorded ahead, %s (%s): %d of 2 identical to a brand-new plugin's render\n",
                view.name.c_str(), what.c_str(), identical);
    vkFreeCommandBuffers(g.device, e.pool, 2, cmds.data());
}

// Two plugins recording at the same time on two threads, each into its own command buffer from
// its own pool; the engine submits both from this thread (a queue is not shared between threads).
CallCounts runTwoThreads(Engine& e, std::array<View, 2>& views, uint32_t frames) {
    setPhase("two threads");
    Gpu& g = e.gpu;
    constexpr uint32_t kInFlight = 2;
    std::array<VkCommandPool, 2> pools{};
    std::array<std::vector<VkCommandBuffer>, 2> cmds;
    for (size_t t = 0; t < 2; ++t) {
        VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        poolInfo.queueFamilyIndex = g.family;
        VK(vkCreateCommandPool(g.device, &poolInfo, nullptr, &pools[t]));
        cmds[t] = e.allocateCommandBuffers(pools[t], kInFlight);
        lightscatter::PluginCreateInfo info;
        info.framesInFlight = kInFlight;
        info.context = g.context();
        info.getInstanceProcAddr = &frame_loop::countingGetInstanceProcAddr;
        views[t].plugin = std::make_unique<lightscatter::Plugin>(info);
    }
    std::array<VkFence, kInFlight> fences{e.createFence(true), e.createFence(true)};
    std::array<std::array<uint64_t, 2>, kInFlight> numbers{};
    e.depthPattern(kSmall);  // made here: the threads only read the engine's patterns
    const CallCounts before = callCounts();
    for (uint32_t frame = 1; frame <= frames; ++frame) {
        const uint32_t slot = frame % kInFlight;
        VK(vkWaitForFences(g.device, 1, &fences[slot], VK_TRUE, UINT64_MAX));
        VK(vkResetFences(g.device, 1, &fences[slot]));
        for (size_t t = 0; t < 2; ++t)
            if (numbers[slot][t] != 0 && !views[t].plugin->report(numbers[slot][t]).timed)
                fail(views[t].name + ": a frame is not timed once its fence signalled");
        Scene scene;
        scene.fogScale = 1.0f + 0.5f * std::sin(0.5f * float(frame));
        scene.g = 0.6f + 0.2f * std::sin(0.3f * float(frame));
        scene.timeSeconds = frame / 60.0;
        std::latch start(2);
        std::array<std::exception_ptr, 2> errors;
        auto recordOn = [&](size_t t) {
            try {
                const VkCommandBuffer cmd = cmds[t][slot];
                Engine::begin(cmd);
                e.recordScene(cmd, {&views[t]}, nullptr);
                const lightscatter::FrameDescription description =
                    describe(views[t], scene, e.shadowMap.image, ShadowState::Uploaded);
                start.arrive_and_wait();  // both plugins record at once
                numbers[slot][t] = views[t].plugin->record(cmd, description);
                VK(vkEndCommandBuffer(cmd));
            } catch (...) {
                errors[t] = std::current_exception();
            }
        };
        std::thread first(recordOn, 0), second(recordOn, 1);
        first.join();
        second.join();
        for (const std::exception_ptr& error : errors)
            if (error) std::rethrow_exception(error);
        e.submit({cmds[0][slot], cmds[1][slot]}, fences[slot]);
    }
    VK(vkQueueWaitIdle(g.queue));
    const CallCounts calls = callCounts() - before;
    for (VkFence f : fences) vkDestroyFence(g.device, f, nullptr);
    for (size_t t = 0; t < 2; ++t) {
        views[t].plugin.reset();
        vkDestroyCommandPool(g.device, pools[t], nullptr);
    }
    return calls;
}

// ---- The table -------------------------------------------------------------------------------

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

void printTable(const RunResult& r) {
    std::printf(
        "\nframes in flight: %u (two views, one command buffer a frame; %u frames, %.1f s)\n"
        "plugin construction, both views: %llu waits, %llu submits, %llu pipelines, %llu "
        "allocations (%.1f KiB)\n",
        r.framesInFlight, kFrames, r.seconds,
        static_cast<unsigned long long>(r.construction.waits()),
        static_cast<unsigned long long>(r.construction.submits()),
        static_cast<unsigned long long>(r.construction.pipelines),
        static_cast<unsigned long long>(r.construction.allocations),
        double(r.construction.allocatedBytes) / 1024.0);
    std::printf("%-26s %1s %6s %-20s %5s %7s %6s %9s %6s %9s %17s %10s\n", "event", "#", "frames",
                "method (A,B)", "waits", "submits", "graphs", "pipelines", "allocs", "alloc KiB",
                "record ms med/max", "in use KiB");
    for (size_t k = 0; k < kKinds; ++k)
        for (int occurrence = 1; occurrence <= 2; ++occurrence) {
            uint32_t frames = 0, graphs = 0;
            CallCounts calls;
            std::vector<double> ms;
            std::set<std::string> methods;
            int64_t inUse = 0;
            for (const FrameStats& f : r.frames) {
                if (static_cast<size_t>(f.kind) != k || f.occurrence != occurrence) continue;
                ++frames;
                graphs += f.graphsCompiled;
                calls.deviceWaitIdle += f.calls.deviceWaitIdle;
                calls.queueWaitIdle += f.calls.queueWaitIdle;
                calls.waitForFences += f.calls.waitForFences;
                calls.queueSubmit += f.calls.queueSubmit;
                calls.queueSubmit2 += f.calls.queueSubmit2;
                calls.pipelines += f.calls.pipelines;
                calls.allocations += f.calls.allocations;
                calls.allocatedBytes += f.calls.allocatedBytes;
                ms.insert(ms.end(), f.recordMs.begin(), f.recordMs.end());
                methods.insert(f.methods.begin(), f.methods.end());
                inUse = f.bytesInUse;
            }
            if (frames == 0) continue;
            std::string method;
            for (const std::string& m : methods) method += (method.empty() ? "" : ",") + m;
            char timing[32];
            std::snprintf(timing, sizeof timing, "%.2f/%.2f", median(ms),
                          *std::max_element(ms.begin(), ms.end()));
            std::printf("%-26s %1d %6u %-20s %5llu %7llu %6u %9llu %6llu %9.1f %17s %10.1f\n",
                        occurrence == 1 ? kKindInfo[k].name : "", occurrence, frames,
                        method.c_str(), static_cast<unsigned long long>(calls.waits()),
                        static_cast<unsigned long long>(calls.submits()), graphs,
                        static_cast<unsigned long long>(calls.pipelines),
                        static_cast<unsigned long long>(calls.allocations),
                        double(calls.allocatedBytes) / 1024.0, timing, double(inUse) / 1024.0);
        }
    std::printf("checkpoints identical to a brand-new plugin's render: %d of %d\n",
                r.checkpointsIdentical, r.checkpointsCompared);
}

// ---- Many lights --------------------------------------------------------------------------------

// Up to eight spots over the floor, each with its own id (LightInput::id): they enter, leave from
// the middle of the list, come back in other orders, and six of them stay away long enough to be
// forgotten. Each phase is the lights of `order`, from its first frame to the next phase's.
struct LightPhase {
    uint32_t frame;
    const char* what;
    std::vector<int> order;  // the lights, by index, in the list's order; empty: shuffled all 8
    bool builds;             // its first frame may compile a graph and allocate
};
const LightPhase kLightPhases[] = {
    {1, "4 lights enter", {0, 1, 2, 3}, true},
    {11, "8 lights", {0, 1, 2, 3, 4, 5, 6, 7}, true},
    {21, "8 lights, reversed", {7, 6, 5, 4, 3, 2, 1, 0}, false},
    {31, "8 lights, shuffled each frame", {}, false},
    {41, "2 leave the middle", {0, 1, 3, 4, 6, 7}, true},
    {51, "they come back, shuffled", {}, false},
    {61, "6 leave for 80 frames", {0, 1}, true},
    {141, "all 8 back, shuffled", {}, true},
};
constexpr uint32_t kLightFrames = 150;

lightscatter::LightInput spotLight(int k) {
    lightscatter::LightInput in;
    lightscatter::Light& l = in.light;
    l.type = lightscatter::LightType::Spot;
    const float a = 0.785f * float(k);
    l.position = {2.5f * std::cos(a), 5.0f, 2.5f * std::sin(a)};
    l.direction = {-0.2f * std::cos(a), -1.0f, -0.2f * std::sin(a)};
    l.intensity = {10.0f + 4.0f * float(k), 30.0f, 45.0f - 4.0f * float(k)};
    l.innerConeAngleDegrees = l.outerConeAngleDegrees = 25.0f;
    in.id = 100 + uint64_t(k);
    return in;
}

// The loop over kLightPhases with one view: no wait, no submit; a graph compiled and memory
// allocated only in a phase's first frame that `builds`; record()'s CPU time per phase.
void runManyLights(Engine& e, View& view, uint32_t framesInFlight) {
    Gpu& g = e.gpu;
    lightscatter::PluginCreateInfo info;
    info.framesInFlight = framesInFlight;
    info.context = g.context();
    info.getInstanceProcAddr = &frame_loop::countingGetInstanceProcAddr;
    view.plugin = std::make_unique<lightscatter::Plugin>(info);
    struct LightSlot {
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        VkFence fence = VK_NULL_HANDLE;
        uint64_t number = 0;
        uint32_t phase = 0;
    };
    std::vector<LightSlot> slots(framesInFlight);
    const std::vector<VkCommandBuffer> cmds = e.allocateCommandBuffers(e.pool, framesInFlight);
    for (uint32_t i = 0; i < framesInFlight; ++i) {
        slots[i].cmd = cmds[i];
        slots[i].fence = e.createFence(false);
    }
    const size_t phases = std::size(kLightPhases);
    std::vector<std::vector<double>> ms(phases);
    std::vector<uint32_t> compiled(phases, 0), pipelines(phases, 0), allocations(phases, 0);
    std::mt19937 shuffle(7);
    auto completed = [&](LightSlot& slot) {
        if (slot.number == 0) return;
        if (view.plugin->report(slot.number).graphCompiled) ++compiled[slot.phase];
        slot.number = 0;
    };
    size_t phase = 0;
    for (uint32_t frame = 1; frame <= kLightFrames; ++frame) {
        LightSlot& slot = slots[(frame - 1) % framesInFlight];
        if (slot.number != 0) {
            VK(vkWaitForFences(g.device, 1, &slot.fence, VK_TRUE, UINT64_MAX));
            VK(vkResetFences(g.device, 1, &slot.fence));
            completed(slot);
        }
        while (phase + 1 < phases && kLightPhases[phase + 1].frame <= frame) ++phase;
        const LightPhase& p = kLightPhases[phase];
        setPhase("many lights, F=" + std::to_string(framesInFlight) + ", frame " +
                 std::to_string(frame) + ", " + p.what);
        std::vector<int> order = p.order;
        if (order.empty()) {
            order = {0, 1, 2, 3, 4, 5, 6, 7};
            std::shuffle(order.begin(), order.end(), shuffle);
        }
        Scene scene;
        lightscatter::FrameDescription d =
            describe(view, scene, e.shadowMap.image, ShadowState::Uploaded);
        d.light = {};
        for (int k : order) d.lights.push_back(spotLight(k));
        Engine::begin(slot.cmd);
        e.recordScene(slot.cmd, {&view}, nullptr);
        const CallCounts before = callCounts();
        const auto t0 = std::chrono::steady_clock::now();
        slot.number = view.plugin->record(slot.cmd, d);
        const auto t1 = std::chrono::steady_clock::now();
        const CallCounts calls = callCounts() - before;
        ms[phase].push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        pipelines[phase] += uint32_t(calls.pipelines);
        allocations[phase] += uint32_t(calls.allocations);
        if (calls.waits() != 0 || calls.submits() != 0)
            fail("record() called " + describeCounts(calls));
        const bool mayBuild = p.builds && frame == p.frame;
        if (!mayBuild && (calls.pipelines != 0 || calls.allocations != 0))
            fail("record() created " + std::to_string(calls.pipelines) +
                 " pipeline(s) and allocated " + std::to_string(calls.allocations) +
                 " block(s) outside a phase's first frame that may build");
        VK(vkEndCommandBuffer(slot.cmd));
        e.submit({slot.cmd}, slot.fence);
        slot.phase = uint32_t(phase);
    }
    for (LightSlot& slot : slots) {
        if (slot.number != 0) VK(vkWaitForFences(g.device, 1, &slot.fence, VK_TRUE, UINT64_MAX));
        completed(slot);
        vkDestroyFence(g.device, slot.fence, nullptr);
    }
    vkFreeCommandBuffers(g.device, e.pool, framesInFlight, cmds.data());
    std::printf("\nmany lights, frames in flight: %u (one view, spots with ids, %u frames)\n",
                framesInFlight, kLightFrames);
    std::printf("%-32s %6s %6s %9s %6s %17s\n", "phase", "frames", "graphs", "pipelines", "allocs",
                "record ms med/max");
    for (size_t k = 0; k < phases; ++k) {
        char timing[32];
        std::snprintf(timing, sizeof timing, "%.2f/%.2f", median(ms[k]),
                      *std::max_element(ms[k].begin(), ms[k].end()));
        std::printf("%-32s %6zu %6u %9u %6u %17s\n", kLightPhases[k].what, ms[k].size(),
                    compiled[k], pipelines[k], allocations[k], timing);
        if (compiled[k] > (kLightPhases[k].builds ? 1u : 0u))
            fail(std::string("many lights: phase '") + kLightPhases[k].what + "' compiled " +
                 std::to_string(compiled[k]) + " graph(s)");
    }
    if (allocations[phases - 1] == 0)
        fail(
            "many lights: the lights forgotten after 80 frames away came back to memory they "
            "kept");
    view.plugin.reset();
}

// A graph compiled other than at an event's first frame the first time: the plugin keeps the last
// 8 graphs it used, and this loop needs fewer configurations than that.
void checkGraphsReused(const RunResult& r) {
    for (uint32_t i = 0; i < kFrames; ++i) {
        const FrameStats& f = r.frames[i];
        if (!(f.occurrence == 1 && f.eventFrame) && f.graphsCompiled != 0)
            fail("F=" + std::to_string(r.framesInFlight) + " frame " + std::to_string(i + 1) +
                 " (" + kKindInfo[static_cast<size_t>(f.kind)].name + ", occurrence " +
                 std::to_string(f.occurrence) + ") compiled a frame graph");
    }
}

int run() {
    const auto started = std::chrono::steady_clock::now();
    Engine e;
    e.create();
    std::array<View, 2> views;
    views[0].name = "view A";
    views[0].eye = {0.0f, 2.5f, 9.0f};
    views[0].target = {0.0f, 1.5f, 0.0f};
    views[1].name = "view B";
    views[1].eye = {6.0f, 2.0f, 6.0f};
    views[1].target = {0.0f, 1.5f, 0.0f};
    views[1].profile = lightscatter::Profile::LowHighPerformance;
    views[1].shadowedMethod = "epipolar";

    for (uint32_t framesInFlight = gDriverHandles ? 2 : 1;
         framesInFlight <= (gDriverHandles ? 2 : 3); ++framesInFlight) {
        for (View& v : views) e.makeViewImages(v, kSmall);
        const RunResult r = runFrameLoop(e, views, framesInFlight);
        setPhase("F=" + std::to_string(framesInFlight) + ", after the loop");
        printTable(r);
        checkGraphsReused(r);
        std::fflush(stdout);
        if (framesInFlight >= 2) {
            // The same graph with the fog of each frame; then another graph, on the same
            // transient memory, for the second frame.
            Scene fog[2], switched[2];
            fog[1].fogScale = 1.5f;
            switched[0].shadow = true;
            switched[1].thinMedium = true;
            for (Scene* pair : {fog, switched})
                for (int i = 0; i < 2; ++i) pair[i].timeSeconds = 10.0 + i / 60.0;
            runRecordAhead(e, views[0], "fog x1.0, then x1.5", fog);
            runRecordAhead(e, views[1], "shadowed epipolar, then analytic", switched);
        }
        VK(vkDeviceWaitIdle(e.gpu.device));
        for (View& v : views) {
            v.plugin.reset();
            e.buryViewImages(v, 0, true);
        }
        e.graveyard.collectAll();
    }

    for (uint32_t framesInFlight : {2u, 3u}) {
        e.makeViewImages(views[0], kSmall);
        runManyLights(e, views[0], framesInFlight);
        VK(vkDeviceWaitIdle(e.gpu.device));
        e.buryViewImages(views[0], 0, true);
        e.graveyard.collectAll();
    }

    for (View& v : views) e.makeViewImages(v, kSmall);
    constexpr uint32_t kThreadFrames = 20;
    const CallCounts threaded = runTwoThreads(e, views, kThreadFrames);
    std::printf("\ntwo threads, %u frames each: %llu waits, %llu submits by the plugins\n",
                kThreadFrames, static_cast<unsigned long long>(threaded.waits()),
                static_cast<unsigned long long>(threaded.submits()));
    if (threaded.waits() != 0 || threaded.submits() != 0)
        fail("two threads: the plugins called " + describeCounts(threaded));
    for (View& v : views) e.buryViewImages(v, 0, true);

    setPhase("teardown");
    const int64_t leftInUse = callCounts().bytesInUse;
    if (leftInUse != 0)
        fail("the plugins' device memory not freed at their destruction: " +
             std::to_string(leftInUse) + " bytes");
    e.destroyAll();
    std::printf("\n%d validation message(s), %d failure(s), %.1f s\n", gMessages, gFailures,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    return gFailures == 0 && gMessages == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--driver-handles") == 0) {
            gDriverHandles = true;
        } else if (std::strcmp(argv[i], "--no-validation") == 0) {
            gNoValidation = true;
        } else {
            std::fprintf(stderr, "consumer_frame_loop: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    try {
        return run();
    } catch (const lightscatter::InvalidInput& e) {
        std::fprintf(stderr, "refused (%s): %s\n", gPhase.c_str(), e.what());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error (%s): %s\n", gPhase.c_str(), e.what());
    }
    return 1;
}
