// hello_shafts: the smallest engine around lightscatter. One 8-bit sRGB color target (as an
// engine without an HDR target has), a camera depth and a spot light's shadow map, one unshadowed
// point light and a fog; the plugin composites the shafts into the color. An engine renders its
// depth and shadow map; this one computes them on the CPU for a floor and a floating slab (so
// that it needs no shaders of its own) and uploads them. It writes the frame to a PNG and exits 1
// on any validation message or error. docs/integration.md quotes it.
//     hello_shafts [out.png]
#include <vulkan/vulkan.h>

#define GLM_FORCE_DEPTH_ZERO_TO_ONE
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>

namespace {

int gMessages = 0;
VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                         VkDebugUtilsMessageTypeFlagsEXT,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    std::fprintf(stderr, "[validation] %s\n", data->pMessage);
    ++gMessages;
    return VK_FALSE;
}
void check(VkResult r, const char* call) {
    if (r != VK_SUCCESS) throw std::runtime_error(std::string(call) + ": " + std::to_string(r));
}
#define VK(call) check((call), #call)

constexpr VkExtent2D kScreen{320, 180};
constexpr uint32_t kShadowSize = 512;

// Vulkan clip space (y down, depth 0 to 1) from GLM's.
glm::mat4 vulkanPerspective(float fovY, float aspect, float nearZ, float farZ) {
    glm::mat4 p = glm::perspective(glm::radians(fovY), aspect, nearZ, farZ);
    p[1][1] = -p[1][1];
    return p;
}
lightscatter::Mat4 toPlugin(const glm::mat4& m) {
    lightscatter::Mat4 out;
    std::memcpy(out.data(), &m[0][0], sizeof out);
    return out;
}

// The scene: the floor y = 0 and a slab 1.5 m above it (|x|, |z| < 0.8, 0.2 thick). The depth of
// the nearest hit of the ray through each pixel of `viewProj`, as a rasterizer stores it.
std::vector<float> depthOf(const glm::mat4& viewProj, uint32_t w, uint32_t h) {
    const glm::mat4 inverse = glm::inverse(viewProj);
    std::vector<float> depth(size_t{w} * h, 1.0f);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const glm::vec2 ndc{(x + 0.5f) / w * 2 - 1, (y + 0.5f) / h * 2 - 1};
            const glm::vec4 a = inverse * glm::vec4(ndc, 0, 1), b = inverse * glm::vec4(ndc, 1, 1);
            const glm::vec3 o = glm::vec3(a) / a.w, d = glm::vec3(b) / b.w - o;
            float t = 2.0f;  // along d, 1 at the far plane
            if (d.y < 0) t = -o.y / d.y;
            for (const float plane : {1.5f, 1.7f}) {  // the slab's bottom and top
                const float s = (plane - o.y) / d.y;
                const glm::vec3 p = o + s * d;
                if (s > 0 && s < t && std::abs(p.x) < 0.8f && std::abs(p.z) < 0.8f) t = s;
            }
            if (t <= 1.0f) {
                const glm::vec4 clip = viewProj * glm::vec4(o + t * d, 1);
                depth[size_t{y} * w + x] = clip.z / clip.w;
            }
        }
    return depth;
}

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
};

struct Vulkan {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t family = 0;
    VkCommandPool pool = VK_NULL_HANDLE;
    lightscatter::DeviceFeatures features;

    uint32_t memoryType(uint32_t bits, VkMemoryPropertyFlags flags) const {
        VkPhysicalDeviceMemoryProperties props;
        vkGetPhysicalDeviceMemoryProperties(physical, &props);
        for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
            if ((bits >> i & 1) && (props.memoryTypes[i].propertyFlags & flags) == flags) return i;
        throw std::runtime_error("no memory type");
    }
    Image image(VkFormat format, VkExtent2D extent, VkImageUsageFlags usage) const {
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = format;
        info.extent = {extent.width, extent.height, 1};
        info.mipLevels = info.arrayLayers = 1;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.usage = usage | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        Image i;
        VK(vkCreateImage(device, &info, nullptr, &i.image));
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(device, i.image, &req);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, nullptr, req.size,
                                   memoryType(req.memoryTypeBits, 0)};
        VK(vkAllocateMemory(device, &alloc, nullptr, &i.memory));
        VK(vkBindImageMemory(device, i.image, i.memory, 0));
        return i;
    }
    // A host-visible buffer of `bytes` and its mapping.
    std::pair<VkBuffer, VkDeviceMemory> buffer(VkDeviceSize bytes, void** mapped) const {
        VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        info.size = bytes;
        info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        VkBuffer b;
        VK(vkCreateBuffer(device, &info, nullptr, &b));
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(device, b, &req);
        VkMemoryAllocateInfo alloc{
            VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, nullptr, req.size,
            memoryType(req.memoryTypeBits,
                       VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT)};
        VkDeviceMemory m;
        VK(vkAllocateMemory(device, &alloc, nullptr, &m));
        VK(vkBindBufferMemory(device, b, m, 0));
        VK(vkMapMemory(device, m, 0, bytes, 0, mapped));
        return {b, m};
    }
};

void barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
             VkImageLayout to) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = b.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    b.srcAccessMask = b.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, 1, 0, 1};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
}

Vulkan createVulkan() {
    Vulkan vk;
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkDebugUtilsMessengerCreateInfoEXT messenger{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
    messenger.pfnUserCallback = &onMessage;
    const VkValidationFeatureEnableEXT sync =
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT, &messenger, 1,
                                     &sync};
    // [device]
    // Vulkan 1.3: the plugin needs it (and is told so: VulkanContext::apiVersion).
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, &features};
    instanceInfo.pApplicationInfo = &app;
    instanceInfo.enabledLayerCount = 1;
    instanceInfo.ppEnabledLayerNames = &layer;
    instanceInfo.enabledExtensionCount = 1;
    instanceInfo.ppEnabledExtensionNames = &extension;
    VK(vkCreateInstance(&instanceInfo, nullptr, &vk.instance));
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(vk.instance, "vkCreateDebugUtilsMessengerEXT"));
    VK(create(vk.instance, &messenger, nullptr, &vk.messenger));
    uint32_t count = 1;
    vkEnumeratePhysicalDevices(vk.instance, &count, &vk.physical);  // the first device will do
    // The plugin's extensions and features (dualSrcBlend where the device has it).
    vk.features = lightscatter::requiredDeviceFeatures(vk.instance, vk.physical);
    const std::vector<const char*> extensions = lightscatter::requiredDeviceExtensions();
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = vk.family;  // family 0: graphics, compute and timestamps here
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, vk.features.chain()};
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queue;
    deviceInfo.enabledExtensionCount = uint32_t(extensions.size());
    deviceInfo.ppEnabledExtensionNames = extensions.data();
    VK(vkCreateDevice(vk.physical, &deviceInfo, nullptr, &vk.device));
    // [device]
    vkGetDeviceQueue(vk.device, vk.family, 0, &vk.queue);
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.queueFamilyIndex = vk.family;
    VK(vkCreateCommandPool(vk.device, &pool, nullptr, &vk.pool));
    return vk;
}

}  // namespace

int main(int argc, char** argv) try {
    const std::string out = argc > 1 ? argv[1] : "hello_shafts.png";
    Vulkan vk = createVulkan();

    // The engine's images: an 8-bit sRGB color target, a camera depth, a spot's shadow map.
    const Image color =
        vk.image(VK_FORMAT_R8G8B8A8_SRGB, kScreen, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
    const Image depth = vk.image(VK_FORMAT_D32_SFLOAT, kScreen, VK_IMAGE_USAGE_SAMPLED_BIT);
    const Image shadow =
        vk.image(VK_FORMAT_D32_SFLOAT, {kShadowSize, kShadowSize}, VK_IMAGE_USAGE_SAMPLED_BIT);
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 1.6f, 6), glm::vec3(0, 1.2f, 0), {0, 1, 0});
    const glm::mat4 projection = vulkanPerspective(60.0f, 16.0f / 9.0f, 0.1f, 50.0f);
    const glm::vec3 spotAt{0.3f, 4.5f, 0.2f};
    const glm::mat4 spotViewProj = vulkanPerspective(50.0f, 1.0f, 0.5f, 20.0f) *
                                   glm::lookAt(spotAt, spotAt - glm::vec3(0, 1, 0), {0, 0, 1});

    // The engine's frame up to the plugin: its color cleared (a grey room), depth and shadow map
    // uploaded (an engine renders them).
    const std::vector<float> camera = depthOf(projection * view, kScreen.width, kScreen.height);
    const std::vector<float> map = depthOf(spotViewProj, kShadowSize, kShadowSize);
    void* mapped = nullptr;
    const auto [staging, stagingMemory] =
        vk.buffer((camera.size() + map.size()) * sizeof(float), &mapped);
    std::memcpy(mapped, camera.data(), camera.size() * sizeof(float));
    std::memcpy(static_cast<float*>(mapped) + camera.size(), map.data(), map.size() * 4);
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr,
                                         vk.pool, VK_COMMAND_BUFFER_LEVEL_PRIMARY, 1};
    VkCommandBuffer cmd;
    VK(vkAllocateCommandBuffers(vk.device, &allocate, &cmd));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK(vkBeginCommandBuffer(cmd, &begin));
    const VkImageLayout dst = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    barrier(cmd, color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, dst);
    const VkClearColorValue grey{{0.18f, 0.18f, 0.2f, 1.0f}};
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, color.image, dst, &grey, 1, &all);
    barrier(cmd, color.image, VK_IMAGE_ASPECT_COLOR_BIT, dst,
            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    VkDeviceSize offset = 0;
    for (const auto& [image, extent] :
         {std::pair{depth.image, kScreen},
          std::pair{shadow.image, VkExtent2D{kShadowSize, kShadowSize}}}) {
        barrier(cmd, image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED, dst);
        VkBufferImageCopy copy{offset, 0,
                               0,      {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1},
                               {},     {extent.width, extent.height, 1}};
        vkCmdCopyBufferToImage(cmd, staging, image, dst, 1, &copy);
        barrier(cmd, image, VK_IMAGE_ASPECT_DEPTH_BIT, dst, read);
        offset += VkDeviceSize{extent.width} * extent.height * sizeof(float);
    }

    // [frame]
    // The plugin, once: on the engine's device, two frames in flight (this engine has one).
    lightscatter::PluginCreateInfo info;
    info.context = {vk.instance, vk.physical, vk.device, vk.queue, vk.family, vk.features.chain()};
    info.context.apiVersion = VK_API_VERSION_1_3;  // the instance's, which Vulkan cannot report
    auto shafts = std::make_unique<lightscatter::Plugin>(info);

    // Each frame: the engine's images as they stand, and where to leave them.
    lightscatter::FrameDescription frame;
    frame.color = {color.image, VK_FORMAT_R8G8B8A8_SRGB, kScreen,
                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                       VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    frame.color.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;  // next: the engine's copy
    frame.depth = {depth.image, VK_FORMAT_D32_SFLOAT, kScreen,
                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                       VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                   read};
    frame.depth.finalLayout = read;
    frame.camera.view = toPlugin(view);
    frame.camera.projection = toPlugin(projection);
    frame.medium.betaM = {0.04f, 0.04f, 0.04f};  // a light fog, 1/m
    frame.medium.g = 0.7f;

    // The lights carry no units in this engine: ask for shafts of a brightness it can show.
    lightscatter::ShaftGoal goal;
    goal.brightness = 0.15f;  // of the 8-bit target's 1.0
    goal.viewDistance = 6.0f;
    goal.lightDistance = 3.0f;
    goal.beamWidth = 2.0f;
    lightscatter::LightInput spot;
    spot.light.type = lightscatter::LightType::Spot;
    spot.light.position = {spotAt.x, spotAt.y, spotAt.z};
    spot.light.direction = {0, -1, 0};
    spot.light.innerConeAngleDegrees = 18.0f;
    spot.light.outerConeAngleDegrees = 22.0f;  // within the shadow map's 25-degree half-angle
    spot.light.intensity =
        lightscatter::shaftIntensity(lightscatter::LightType::Spot, frame.medium, goal);
    spot.light.shadowViewProjection = toPlugin(spotViewProj);
    spot.light.shadowMapSize = kShadowSize;
    spot.shadowMap =
        lightscatter::ImageInput{shadow.image,
                                 VK_FORMAT_D32_SFLOAT,
                                 {kShadowSize, kShadowSize},
                                 VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                     VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                 read};
    spot.shadowMap->finalLayout = read;
    lightscatter::LightInput point;  // no shadow map: lit all round, its closed form
    point.light.type = lightscatter::LightType::Point;
    point.light.position = {-2.5f, 1.0f, -1.0f};
    goal.brightness = 0.05f;
    goal.lightDistance = 1.0f;
    point.light.intensity =
        lightscatter::shaftIntensity(lightscatter::LightType::Point, frame.medium, goal);
    frame.lights = {spot, point};
    frame.method = lightscatter::Method::Auto;  // a method per light, as each needs

    // Outside any render pass: the plugin records its own passes (compute and graphics).
    const uint64_t number = shafts->record(cmd, frame);
    // [frame]

    void* pixels = nullptr;
    const auto [readback, readbackMemory] =
        vk.buffer(VkDeviceSize{kScreen.width} * kScreen.height * 4, &pixels);
    VkBufferImageCopy copy{
        0, 0, 0, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, {}, {kScreen.width, kScreen.height, 1}};
    vkCmdCopyImageToBuffer(cmd, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback, 1,
                           &copy);
    VkMemoryBarrier2 toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2, nullptr,
                            VK_PIPELINE_STAGE_2_COPY_BIT,       VK_ACCESS_2_TRANSFER_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_HOST_BIT,       VK_ACCESS_2_HOST_READ_BIT};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &toHost;
    vkCmdPipelineBarrier2(cmd, &dep);
    VK(vkEndCommandBuffer(cmd));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    VK(vkQueueSubmit(vk.queue, 1, &submit, VK_NULL_HANDLE));
    VK(vkQueueWaitIdle(vk.queue));
    const lightscatter::FrameReport report = shafts->report(number);
    std::printf("%s: %s (%.2f ms of GPU time)\n", report.method.c_str(), report.reason.c_str(),
                report.totalMilliseconds);
    if (!stbi_write_png(out.c_str(), int(kScreen.width), int(kScreen.height), 4, pixels,
                        int(kScreen.width) * 4))
        throw std::runtime_error("could not write " + out);
    std::printf("wrote %s\n", out.c_str());

    // The shaft under the spot is brighter than the grey room around it.
    const auto* p = static_cast<const uint8_t*>(pixels);
    const auto at = [&](glm::vec3 world) {
        const glm::vec4 c = projection * view * glm::vec4(world, 1);
        const uint32_t x = uint32_t((c.x / c.w * 0.5f + 0.5f) * kScreen.width);
        const uint32_t y = uint32_t((c.y / c.w * 0.5f + 0.5f) * kScreen.height);
        return p[(size_t{y} * kScreen.width + x) * 4];
    };
    const int shaft = at({0.3f, 2.5f, 0.2f}), room = at({2.5f, 3.0f, -3.0f});
    std::printf("shaft %d, room %d (8-bit sRGB)\n", shaft, room);

    // The plugin goes before the device it works on.
    shafts.reset();
    for (const Image& i : {color, depth, shadow}) {
        vkDestroyImage(vk.device, i.image, nullptr);
        vkFreeMemory(vk.device, i.memory, nullptr);
    }
    for (const auto& [b, m] :
         {std::pair{staging, stagingMemory}, std::pair{readback, readbackMemory}}) {
        vkDestroyBuffer(vk.device, b, nullptr);
        vkFreeMemory(vk.device, m, nullptr);
    }
    vkDestroyCommandPool(vk.device, vk.pool, nullptr);
    vkDestroyDevice(vk.device, nullptr);
    reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(vkGetInstanceProcAddr(
        vk.instance, "vkDestroyDebugUtilsMessengerEXT"))(vk.instance, vk.messenger, nullptr);
    vkDestroyInstance(vk.instance, nullptr);
    return gMessages == 0 && shaft > room + 20 ? 0 : 1;
} catch (const std::exception& e) {
    std::fprintf(stderr, "hello_shafts: %s\n", e.what());
    return 1;
}
