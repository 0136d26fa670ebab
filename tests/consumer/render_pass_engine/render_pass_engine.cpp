// A headless engine like the one issue #38's report tried the plugin in (Sascha Willems' Vulkan
// examples, `shadowmapping`), written here from scratch: a Vulkan 1.0-style framework (a
// VulkanDevice whose createLogicalDevice takes VkPhysicalDeviceFeatures and a pNext chain apart
// and builds its own VkPhysicalDeviceFeatures2), VkRenderPass and framebuffers (no dynamic
// rendering), GLM matrices, two frames in flight with a fence each, a spot light with a D16 shadow
// map rendered in a depth-only render pass, a D32_SFLOAT_S8_UINT camera depth, forward shading
// with no light units (N.L) straight into a B8G8R8A8_SRGB target that stands for the swapchain
// image, and a UI overlay drawn over the scene. Its shaders are GLSL compiled at build time.
//
// It builds twice from this one file: without the plugin (LS_WITH_PLUGIN=0) and with it
// (LS_WITH_PLUGIN=1). Every line that exists only for the plugin is inside an
// `#if LS_WITH_PLUGIN` block or reads LS_WITH_PLUGIN, so the integration's cost is those lines
// (CTest consumer.render_pass_engine.lines counts them: 60 at most). Each build renders 6 frames
// under the validation layer with synchronization validation and writes the last one as a PPM
// (--write FILE); the plugin's build compares its image with the other build's (--baseline FILE,
// shaft_checks.h). Exit code 0, or 1 on a validation message, an exception or a failed check.
#define GLM_FORCE_RADIANS
#define GLM_FORCE_DEPTH_ZERO_TO_ONE
#include <vulkan/vulkan.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "scene_frag.h"
#include "scene_vert.h"
#include "shadow_vert.h"
#include "ui_frag.h"
#include "ui_vert.h"
#if LS_WITH_PLUGIN
#include <lightscatter/lightscatter.h>
#include <bit>
#include "shaft_checks.h"  // the test's checks of the image
#endif

namespace {

constexpr VkExtent2D kExtent{320, 180};
constexpr uint32_t kShadowMapSize = 512;
constexpr VkExtent2D kShadowExtent{kShadowMapSize, kShadowMapSize};
constexpr uint32_t kFramesInFlight = 2;
constexpr uint32_t kFrames = 6;
constexpr VkFormat kColorFormat = VK_FORMAT_B8G8R8A8_SRGB;  // the swapchain's
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT_S8_UINT;
constexpr VkFormat kShadowFormat = VK_FORMAT_D16_UNORM;
constexpr VkImageUsageFlags kColorUsage =
    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;  // a swapchain image's
constexpr VkImageUsageFlags kDepthUsage =  // the plugin samples the depth
    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | (LS_WITH_PLUGIN ? VK_IMAGE_USAGE_SAMPLED_BIT : 0);
constexpr VkImageUsageFlags kShadowUsage =
    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;

int gValidationMessages = 0;

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
    ++gValidationMessages;
    return VK_FALSE;
}

void check(VkResult result, const char* call) {
    if (result != VK_SUCCESS)
        throw std::runtime_error(std::string(call) + " returned " + std::to_string(result));
}
#define VK(call) check((call), #call)

// ---- The framework: Vulkan 1.0 style ------------------------------------------------------------

namespace framework {

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;  // host-visible buffers stay mapped
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
};

struct VulkanDevice {
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice logicalDevice = VK_NULL_HANDLE;
    uint32_t graphicsFamily = 0;
    VkPhysicalDeviceFeatures features{};  // what the device offers
    VkPhysicalDeviceMemoryProperties memoryProperties{};

    explicit VulkanDevice(VkPhysicalDevice physical) : physicalDevice(physical) {
        vkGetPhysicalDeviceFeatures(physical, &features);
        vkGetPhysicalDeviceMemoryProperties(physical, &memoryProperties);
        uint32_t count = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
        std::vector<VkQueueFamilyProperties> families(count);
        vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
        for (graphicsFamily = 0; graphicsFamily < count; ++graphicsFamily)
            if (families[graphicsFamily].queueFlags & VK_QUEUE_GRAPHICS_BIT) return;
        throw std::runtime_error("no graphics queue");
    }

    // As the framework's VulkanDevice::createLogicalDevice: the features and the chain come apart,
    // and a chain makes it build its own VkPhysicalDeviceFeatures2 (pEnabledFeatures must then be
    // null).
    void createLogicalDevice(VkPhysicalDeviceFeatures enabledFeatures,
                             std::vector<const char*> enabledExtensions, void* pNextChain) {
        const float priority = 1.0f;
        VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        queueInfo.queueFamilyIndex = graphicsFamily;
        queueInfo.queueCount = 1;
        queueInfo.pQueuePriorities = &priority;
        VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        info.queueCreateInfoCount = 1;
        info.pQueueCreateInfos = &queueInfo;
        info.enabledExtensionCount = static_cast<uint32_t>(enabledExtensions.size());
        info.ppEnabledExtensionNames = enabledExtensions.data();
        info.pEnabledFeatures = &enabledFeatures;
        VkPhysicalDeviceFeatures2 features2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        if (pNextChain) {
            features2.features = enabledFeatures;
            features2.pNext = pNextChain;
            info.pEnabledFeatures = nullptr;
            info.pNext = &features2;
        }
        VK(vkCreateDevice(physicalDevice, &info, nullptr, &logicalDevice));
    }

    uint32_t memoryType(uint32_t bits, VkMemoryPropertyFlags flags) const {
        for (uint32_t i = 0; i < memoryProperties.memoryTypeCount; ++i)
            if ((bits & (1u << i)) &&
                (memoryProperties.memoryTypes[i].propertyFlags & flags) == flags)
                return i;
        throw std::runtime_error("no suitable memory type");
    }

    // Host-visible, coherent and mapped.
    Buffer createBuffer(VkBufferUsageFlags usage, VkDeviceSize size, const void* data = nullptr) {
        Buffer b;
        VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        info.size = size;
        info.usage = usage;
        VK(vkCreateBuffer(logicalDevice, &info, nullptr, &b.buffer));
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(logicalDevice, b.buffer, &req);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex =
            memoryType(req.memoryTypeBits,
                       VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        VK(vkAllocateMemory(logicalDevice, &alloc, nullptr, &b.memory));
        VK(vkBindBufferMemory(logicalDevice, b.buffer, b.memory, 0));
        VK(vkMapMemory(logicalDevice, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
        if (data) std::memcpy(b.mapped, data, size);
        return b;
    }

    Image createImage(VkFormat format, VkExtent2D extent, VkImageUsageFlags usage,
                      VkImageAspectFlags aspect) {
        Image img;
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = format;
        info.extent = {extent.width, extent.height, 1};
        info.mipLevels = info.arrayLayers = 1;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.tiling = VK_IMAGE_TILING_OPTIMAL;
        info.usage = usage;
        VK(vkCreateImage(logicalDevice, &info, nullptr, &img.image));
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(logicalDevice, img.image, &req);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        VK(vkAllocateMemory(logicalDevice, &alloc, nullptr, &img.memory));
        VK(vkBindImageMemory(logicalDevice, img.image, img.memory, 0));
        VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        viewInfo.image = img.image;
        viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
        viewInfo.format = format;
        viewInfo.subresourceRange = {aspect, 0, 1, 0, 1};
        VK(vkCreateImageView(logicalDevice, &viewInfo, nullptr, &img.view));
        return img;
    }

    void destroy(Buffer& b) {
        vkDestroyBuffer(logicalDevice, b.buffer, nullptr);
        vkFreeMemory(logicalDevice, b.memory, nullptr);
    }
    void destroy(Image& img) {
        vkDestroyImageView(logicalDevice, img.view, nullptr);
        vkDestroyImage(logicalDevice, img.image, nullptr);
        vkFreeMemory(logicalDevice, img.memory, nullptr);
    }
};

VkShaderModule loadShader(VkDevice device, const uint32_t* code, size_t bytes) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = bytes;
    info.pCode = code;
    VkShaderModule module;
    VK(vkCreateShaderModule(device, &info, nullptr, &module));
    return module;
}

}  // namespace framework

// ---- The scene ----------------------------------------------------------------------------------

struct Vertex {
    glm::vec3 position, normal, color;
};

// An axis-aligned box, 36 vertices.
void addBox(std::vector<Vertex>& out, glm::vec3 center, glm::vec3 half, glm::vec3 color) {
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = side;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = side;  // counter-clockwise seen from outside
            auto corner = [&](float a, float b) {
                return Vertex{center + half * (n + a * u + b * v), n, color};
            };
            for (Vertex vertex : {corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, -1),
                                  corner(1, 1), corner(-1, 1)})
                out.push_back(vertex);
        }
}

std::vector<Vertex> buildScene() {
    std::vector<Vertex> v;
    addBox(v, {0.0f, -0.05f, 0.0f}, {25.0f, 0.05f, 20.0f}, {0.7f, 0.7f, 0.7f});  // ground
    addBox(v, {0.0f, 8.0f, -7.0f}, {25.0f, 8.0f, 0.1f}, {0.5f, 0.55f, 0.6f});    // back wall
    addBox(v, {2.6f, 0.6f, 1.0f}, {0.6f, 0.6f, 0.6f}, {0.8f, 0.2f, 0.15f});
    addBox(v, {-2.8f, 0.9f, -1.5f}, {0.5f, 0.9f, 0.5f}, {0.2f, 0.3f, 0.8f});
    // A grille in the spot's beam: its bars' shadows cut the shaft into sheets seen edge-on.
    for (int i = -2; i <= 2; ++i)
        addBox(v, {0.6f * float(i), 4.5f, 0.0f}, {0.1f, 0.06f, 1.8f}, {0.3f, 0.3f, 0.3f});
    return v;
}

// The per-frame uniforms (shaders/scene.glsl).
struct FrameUniforms {
    glm::mat4 viewProjection;
    glm::mat4 lightViewProjection;
    glm::vec4 lightPosition;   // w: cos(inner)
    glm::vec4 lightDirection;  // w: cos(outer)
    glm::vec4 lightColor;      // w: ambient
};

struct PerFrame {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    framework::Buffer uniforms;
    VkDescriptorSet descriptors = VK_NULL_HANDLE;
    framework::Image swapchainImage;  // stands for the image acquired from the swapchain
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    framework::Buffer readback;  // stands for presenting it
};

struct Options {
    std::string write;     // the last frame as a PPM
    std::string baseline;  // the other build's PPM (the plugin's build compares with it)
};

void writePpm(const std::string& path, const uint8_t* bgra, VkExtent2D extent) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot write " + path);
    std::fprintf(f, "P6\n%u %u\n255\n", extent.width, extent.height);
    for (size_t i = 0; i < size_t{extent.width} * extent.height; ++i) {
        const uint8_t rgb[3] = {bgra[4 * i + 2], bgra[4 * i + 1], bgra[4 * i]};
        std::fwrite(rgb, 1, 3, f);
    }
    std::fclose(f);
}

int run(const Options& options) {
    // ---- Instance: validation with synchronization validation, a messenger that counts ----------
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
    app.pApplicationName = "render pass engine";
    app.apiVersion = LS_WITH_PLUGIN ? VK_API_VERSION_1_3 : VK_API_VERSION_1_0;  // the plugin: 1.3
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

    uint32_t count = 0;
    VK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    if (count == 0) throw std::runtime_error("no Vulkan device");
    std::vector<VkPhysicalDevice> physicals(count);
    VK(vkEnumeratePhysicalDevices(instance, &count, physicals.data()));
    framework::VulkanDevice vulkanDevice(physicals[0]);

    // ---- The device: the example's features and extensions, the framework's creation -----------
    VkPhysicalDeviceFeatures enabledFeatures{};
    if (vulkanDevice.features.samplerAnisotropy) enabledFeatures.samplerAnisotropy = VK_TRUE;
    std::vector<const char*> enabledDeviceExtensions;
    void* deviceCreatepNextChain = nullptr;
#if LS_WITH_PLUGIN
    // The plugin's features merged into the example's core ones and into Vulkan 1.1 to 1.3's
    // structures, chained ahead of the example's chain; its extensions.
    lightscatter::DeviceFeatures pluginFeatures;
    pluginFeatures.vulkan13.pNext = std::exchange(deviceCreatepNextChain, &pluginFeatures.vulkan11);
    lightscatter::mergeRequiredDeviceFeatures(enabledFeatures, deviceCreatepNextChain, instance,
                                              vulkanDevice.physicalDevice);
    enabledDeviceExtensions = lightscatter::requiredDeviceExtensions();  // the example has none
#endif
    vulkanDevice.createLogicalDevice(enabledFeatures, enabledDeviceExtensions,
                                     deviceCreatepNextChain);
    const VkDevice device = vulkanDevice.logicalDevice;
    VkQueue queue;
    vkGetDeviceQueue(device, vulkanDevice.graphicsFamily, 0, &queue);

    // ---- Images ------------------------------------------------------------------------------
    framework::Image depth =
        vulkanDevice.createImage(kDepthFormat, kExtent, kDepthUsage,
                                 VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT);
    framework::Image shadowMap = vulkanDevice.createImage(kShadowFormat, kShadowExtent,
                                                          kShadowUsage, VK_IMAGE_ASPECT_DEPTH_BIT);
    VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    samplerInfo.magFilter = samplerInfo.minFilter = VK_FILTER_LINEAR;
    samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW =
        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    samplerInfo.compareEnable = VK_TRUE;
    samplerInfo.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    samplerInfo.maxLod = 1.0f;
    VkSampler shadowSampler;
    VK(vkCreateSampler(device, &samplerInfo, nullptr, &shadowSampler));

    // ---- The shadow map's render pass: depth only, sampled after it --------------------------
    VkAttachmentDescription shadowAttachment{};
    shadowAttachment.format = kShadowFormat;
    shadowAttachment.samples = VK_SAMPLE_COUNT_1_BIT;
    shadowAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    shadowAttachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    shadowAttachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    shadowAttachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    shadowAttachment.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    shadowAttachment.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    VkAttachmentReference shadowRef{0, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription shadowSubpass{};
    shadowSubpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    shadowSubpass.pDepthStencilAttachment = &shadowRef;
    std::array<VkSubpassDependency, 2> shadowDependencies{};
    shadowDependencies[0] = {
        VK_SUBPASS_EXTERNAL,
        0,
        VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
        VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
        VK_ACCESS_SHADER_READ_BIT,
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
        0};
    shadowDependencies[1] = {0,
                             VK_SUBPASS_EXTERNAL,
                             VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                             VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                             VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                             VK_ACCESS_SHADER_READ_BIT,
                             0};
    VkRenderPassCreateInfo shadowPassInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    shadowPassInfo.attachmentCount = 1;
    shadowPassInfo.pAttachments = &shadowAttachment;
    shadowPassInfo.subpassCount = 1;
    shadowPassInfo.pSubpasses = &shadowSubpass;
    shadowPassInfo.dependencyCount = static_cast<uint32_t>(shadowDependencies.size());
    shadowPassInfo.pDependencies = shadowDependencies.data();
    VkRenderPass shadowPass;
    VK(vkCreateRenderPass(device, &shadowPassInfo, nullptr, &shadowPass));
    VkFramebufferCreateInfo shadowFbInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    shadowFbInfo.renderPass = shadowPass;
    shadowFbInfo.attachmentCount = 1;
    shadowFbInfo.pAttachments = &shadowMap.view;
    shadowFbInfo.width = shadowFbInfo.height = kShadowMapSize;
    shadowFbInfo.layers = 1;
    VkFramebuffer shadowFramebuffer;
    VK(vkCreateFramebuffer(device, &shadowFbInfo, nullptr, &shadowFramebuffer));

    // ---- The main render pass: the scene, then the UI over it --------------------------------
    std::array<VkAttachmentDescription, 2> attachments{};
    attachments[0].format = kColorFormat;
    attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    // PRESENT_SRC_KHR with a swapchain; headless, the "present" is a copy.
    attachments[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    attachments[1].format = kDepthFormat;
    attachments[1].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[1].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;  // nothing reads it after
    attachments[1].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[1].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[1].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &colorRef;
    subpass.pDepthStencilAttachment = &depthRef;
    std::array<VkSubpassDependency, 3> dependencies{};
    dependencies[0] = {
        VK_SUBPASS_EXTERNAL,
        0,
        VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
        VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
        0};
    // The color's last use: a swapchain image's acquire semaphore waits at this stage; headless,
    // the copy that stands for presenting it two frames ago.
    dependencies[1] = {
        VK_SUBPASS_EXTERNAL,
        0,
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
        0,
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT,
        0};
    dependencies[2] = {0,
                       VK_SUBPASS_EXTERNAL,
                       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                       VK_ACCESS_TRANSFER_READ_BIT,
                       0};
    VkRenderPassCreateInfo renderPassInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    renderPassInfo.attachmentCount = static_cast<uint32_t>(attachments.size());
    renderPassInfo.pAttachments = attachments.data();
    renderPassInfo.subpassCount = 1;
    renderPassInfo.pSubpasses = &subpass;
    renderPassInfo.dependencyCount = static_cast<uint32_t>(dependencies.size());
    renderPassInfo.pDependencies = dependencies.data();
#if LS_WITH_PLUGIN
    // The plugin records between render passes: the scene's leaves it these, the UI's loads after.
    attachments[0].finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
#endif
    VkRenderPass renderPass;
    VK(vkCreateRenderPass(device, &renderPassInfo, nullptr, &renderPass));
#if LS_WITH_PLUGIN
    attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    attachments[0].initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    attachments[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    VkRenderPass uiRenderPass;  // compatible with the scene's: same framebuffers and pipelines
    VK(vkCreateRenderPass(device, &renderPassInfo, nullptr, &uiRenderPass));
#endif

    // ---- Pipelines ---------------------------------------------------------------------------
    std::array<VkDescriptorSetLayoutBinding, 2> bindings{};
    bindings[0] = {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                   VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    bindings[1] = {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
                   nullptr};
    VkDescriptorSetLayoutCreateInfo setLayoutInfo{
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setLayoutInfo.bindingCount = static_cast<uint32_t>(bindings.size());
    setLayoutInfo.pBindings = bindings.data();
    VkDescriptorSetLayout setLayout;
    VK(vkCreateDescriptorSetLayout(device, &setLayoutInfo, nullptr, &setLayout));
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout;
    VkPipelineLayout pipelineLayout;
    VK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &pipelineLayout));

    const VkShaderModule shadowVert =
        framework::loadShader(device, shadow_vert, sizeof(shadow_vert));
    const VkShaderModule sceneVert = framework::loadShader(device, scene_vert, sizeof(scene_vert));
    const VkShaderModule sceneFrag = framework::loadShader(device, scene_frag, sizeof(scene_frag));
    const VkShaderModule uiVert = framework::loadShader(device, ui_vert, sizeof(ui_vert));
    const VkShaderModule uiFrag = framework::loadShader(device, ui_frag, sizeof(ui_frag));
    auto stage = [](VkShaderStageFlagBits s, VkShaderModule m) {
        VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        info.stage = s;
        info.module = m;
        info.pName = "main";
        return info;
    };

    const VkVertexInputBindingDescription vertexBinding{0, sizeof(Vertex),
                                                        VK_VERTEX_INPUT_RATE_VERTEX};
    const std::array<VkVertexInputAttributeDescription, 3> vertexAttributes{
        {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
         {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
         {2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, color)}}};
    VkPipelineVertexInputStateCreateInfo vertexInput{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertexInput.vertexBindingDescriptionCount = 1;
    vertexInput.pVertexBindingDescriptions = &vertexBinding;
    vertexInput.vertexAttributeDescriptionCount = static_cast<uint32_t>(vertexAttributes.size());
    vertexInput.pVertexAttributeDescriptions = vertexAttributes.data();
    VkPipelineInputAssemblyStateCreateInfo inputAssembly{
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    inputAssembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo viewportState{
        VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewportState.viewportCount = viewportState.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_BACK_BIT;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depthState{
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depthState.depthTestEnable = depthState.depthWriteEnable = VK_TRUE;
    depthState.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    VkPipelineColorBlendAttachmentState blendAttachment{};
    blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                     VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo blend{
        VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = 1;
    blend.pAttachments = &blendAttachment;
    const std::array<VkDynamicState, 2> dynamicStates{VK_DYNAMIC_STATE_VIEWPORT,
                                                      VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = static_cast<uint32_t>(dynamicStates.size());
    dynamic.pDynamicStates = dynamicStates.data();

    std::array<VkPipelineShaderStageCreateInfo, 2> stages{
        stage(VK_SHADER_STAGE_VERTEX_BIT, sceneVert),
        stage(VK_SHADER_STAGE_FRAGMENT_BIT, sceneFrag)};
    VkGraphicsPipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    pipelineInfo.stageCount = 2;
    pipelineInfo.pStages = stages.data();
    pipelineInfo.pVertexInputState = &vertexInput;
    pipelineInfo.pInputAssemblyState = &inputAssembly;
    pipelineInfo.pViewportState = &viewportState;
    pipelineInfo.pRasterizationState = &raster;
    pipelineInfo.pMultisampleState = &multisample;
    pipelineInfo.pDepthStencilState = &depthState;
    pipelineInfo.pColorBlendState = &blend;
    pipelineInfo.pDynamicState = &dynamic;
    pipelineInfo.layout = pipelineLayout;
    pipelineInfo.renderPass = renderPass;
    VkPipeline scenePipeline;
    VK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr,
                                 &scenePipeline));

    // The UI: no vertices, no depth test, drawn over everything.
    stages = {stage(VK_SHADER_STAGE_VERTEX_BIT, uiVert),
              stage(VK_SHADER_STAGE_FRAGMENT_BIT, uiFrag)};
    VkPipelineVertexInputStateCreateInfo noVertices{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    pipelineInfo.pVertexInputState = &noVertices;
    VkPipelineInputAssemblyStateCreateInfo strip = inputAssembly;
    strip.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    pipelineInfo.pInputAssemblyState = &strip;
    VkPipelineRasterizationStateCreateInfo noCull = raster;
    noCull.cullMode = VK_CULL_MODE_NONE;
    pipelineInfo.pRasterizationState = &noCull;
    VkPipelineDepthStencilStateCreateInfo noDepth{
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    pipelineInfo.pDepthStencilState = &noDepth;
    VkPipeline uiPipeline;
    VK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &uiPipeline));

    // The shadow map: depth only, no fragment shader, the framework's depth bias.
    pipelineInfo.stageCount = 1;
    stages[0] = stage(VK_SHADER_STAGE_VERTEX_BIT, shadowVert);
    VkPipelineVertexInputStateCreateInfo positions = vertexInput;
    positions.vertexAttributeDescriptionCount = 1;  // the position only
    pipelineInfo.pVertexInputState = &positions;
    pipelineInfo.pInputAssemblyState = &inputAssembly;
    VkPipelineRasterizationStateCreateInfo biased = noCull;
    biased.depthBiasEnable = VK_TRUE;
    biased.depthBiasConstantFactor = 1.25f;
    biased.depthBiasSlopeFactor = 1.75f;
    pipelineInfo.pRasterizationState = &biased;
    pipelineInfo.pDepthStencilState = &depthState;
    VkPipelineColorBlendStateCreateInfo noColor{
        VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    pipelineInfo.pColorBlendState = &noColor;
    pipelineInfo.renderPass = shadowPass;
    VkPipeline shadowPipeline;
    VK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr,
                                 &shadowPipeline));
    for (VkShaderModule m : {shadowVert, sceneVert, sceneFrag, uiVert, uiFrag})
        vkDestroyShaderModule(device, m, nullptr);

    // ---- The scene, the camera and the light (GLM) -------------------------------------------
    const std::vector<Vertex> vertices = buildScene();
    framework::Buffer vertexBuffer = vulkanDevice.createBuffer(
        VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, vertices.size() * sizeof(Vertex), vertices.data());
    const glm::vec3 eye(0.0f, 3.0f, 13.0f);
    const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f, 3.5f, 0.0f), glm::vec3(0, 1, 0));
    glm::mat4 projection = glm::perspective(
        glm::radians(60.0f), float(kExtent.width) / float(kExtent.height), 0.1f, 40.0f);
    projection[1][1] *= -1.0f;  // Vulkan's clip space: y down
    const glm::vec3 lightPosition(0.0f, 9.0f, 0.0f);
    const glm::vec3 lightDirection = glm::normalize(glm::vec3(0.15f, -1.0f, -0.1f));
    const glm::vec3 lightColor(1.0f, 0.95f, 0.85f);    // no units: N.L shading
    const float innerCone = 20.0f, outerCone = 25.0f;  // degrees
    // The shadow map's frustum, as the framework's shadow mapping makes it (no y flip: the map is
    // rendered and sampled with the same matrix).
    const glm::mat4 lightViewProjection =
        glm::perspective(glm::radians(2.0f * outerCone + 10.0f), 1.0f, 1.0f, 20.0f) *
        glm::lookAt(lightPosition, lightPosition + lightDirection, glm::vec3(0, 0, 1));
    FrameUniforms uniforms;
    uniforms.viewProjection = projection * view;
    uniforms.lightViewProjection = lightViewProjection;
    uniforms.lightPosition = glm::vec4(lightPosition, std::cos(glm::radians(innerCone)));
    uniforms.lightDirection = glm::vec4(lightDirection, std::cos(glm::radians(outerCone)));
    uniforms.lightColor = glm::vec4(lightColor, 0.1f);
#if LS_WITH_PLUGIN
    pluginFeatures.core.features = enabledFeatures;  // the chain the framework's device got
    auto lightShafts = std::make_unique<lightscatter::Plugin>(lightscatter::PluginCreateInfo{
        kFramesInFlight,
        {instance, vulkanDevice.physicalDevice, device, queue, vulkanDevice.graphicsFamily,
         pluginFeatures.chain(), app.apiVersion}});
    lightscatter::FrameDescription frame;
    frame.depth = {depth.image, kDepthFormat, kExtent, kDepthUsage,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    frame.depth.finalLayout = frame.depth.layout;
    frame.shadowMap = {{shadowMap.image, kShadowFormat, kShadowExtent, kShadowUsage,
                        VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL}};
    frame.shadowMap->finalLayout = frame.shadowMap->layout;
    frame.camera.view = std::bit_cast<lightscatter::Mat4>(view);  // GLM's layout
    frame.camera.projection = std::bit_cast<lightscatter::Mat4>(projection);
    frame.light.type = lightscatter::LightType::Spot;
    frame.light.position = std::bit_cast<lightscatter::Vec3>(lightPosition);
    frame.light.direction = std::bit_cast<lightscatter::Vec3>(lightDirection);
    frame.light.innerConeAngleDegrees = innerCone;
    frame.light.outerConeAngleDegrees = outerCone;
    frame.light.shadowViewProjection = std::bit_cast<lightscatter::Mat4>(lightViewProjection);
    frame.light.shadowMapSize = kShadowMapSize;
    frame.medium.betaM = {0.005f, 0.005f, 0.005f};  // 1/m: a light haze
    // The engine's light has no units: the plugin's is as bright as a shaft of 0.08 needs, seen
    // across a 2.5 m wide beam 13 m from the camera, 3 m from the light, at 85 degrees.
    frame.light.intensity = lightscatter::shaftIntensity(frame.light.type, frame.medium,
                                                         {0.08f, 2.5f, 13.0f, 3.0f, 85.0f});
    for (int c = 0; c < 3; ++c) frame.light.intensity[c] *= lightColor[c];
#endif

    // ---- Per frame in flight -----------------------------------------------------------------
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = vulkanDevice.graphicsFamily;
    VkCommandPool commandPool;
    VK(vkCreateCommandPool(device, &poolInfo, nullptr, &commandPool));
    const std::array<VkDescriptorPoolSize, 2> poolSizes{
        {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kFramesInFlight},
         {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kFramesInFlight}}};
    VkDescriptorPoolCreateInfo descriptorPoolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    descriptorPoolInfo.maxSets = kFramesInFlight;
    descriptorPoolInfo.poolSizeCount = static_cast<uint32_t>(poolSizes.size());
    descriptorPoolInfo.pPoolSizes = poolSizes.data();
    VkDescriptorPool descriptorPool;
    VK(vkCreateDescriptorPool(device, &descriptorPoolInfo, nullptr, &descriptorPool));

    std::array<PerFrame, kFramesInFlight> frames;
    const VkDeviceSize imageBytes = VkDeviceSize{kExtent.width} * kExtent.height * 4;
    for (PerFrame& f : frames) {
        VkCommandBufferAllocateInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        cmdInfo.commandPool = commandPool;
        cmdInfo.commandBufferCount = 1;
        VK(vkAllocateCommandBuffers(device, &cmdInfo, &f.cmd));
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        VK(vkCreateFence(device, &fenceInfo, nullptr, &f.fence));
        f.uniforms =
            vulkanDevice.createBuffer(VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, sizeof(FrameUniforms));
        VkDescriptorSetAllocateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        setInfo.descriptorPool = descriptorPool;
        setInfo.descriptorSetCount = 1;
        setInfo.pSetLayouts = &setLayout;
        VK(vkAllocateDescriptorSets(device, &setInfo, &f.descriptors));
        const VkDescriptorBufferInfo bufferInfo{f.uniforms.buffer, 0, sizeof(FrameUniforms)};
        const VkDescriptorImageInfo imageInfo{shadowSampler, shadowMap.view,
                                              VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
        std::array<VkWriteDescriptorSet, 2> writes{};
        for (uint32_t b = 0; b < 2; ++b) {
            writes[b].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
            writes[b].dstSet = f.descriptors;
            writes[b].dstBinding = b;
            writes[b].descriptorCount = 1;
            writes[b].descriptorType = bindings[b].descriptorType;
        }
        writes[0].pBufferInfo = &bufferInfo;
        writes[1].pImageInfo = &imageInfo;
        vkUpdateDescriptorSets(device, 2, writes.data(), 0, nullptr);
        f.swapchainImage =
            vulkanDevice.createImage(kColorFormat, kExtent, kColorUsage, VK_IMAGE_ASPECT_COLOR_BIT);
        const std::array<VkImageView, 2> views{f.swapchainImage.view, depth.view};
        VkFramebufferCreateInfo fbInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fbInfo.renderPass = renderPass;
        fbInfo.attachmentCount = static_cast<uint32_t>(views.size());
        fbInfo.pAttachments = views.data();
        fbInfo.width = kExtent.width;
        fbInfo.height = kExtent.height;
        fbInfo.layers = 1;
        VK(vkCreateFramebuffer(device, &fbInfo, nullptr, &f.framebuffer));
        f.readback = vulkanDevice.createBuffer(VK_BUFFER_USAGE_TRANSFER_DST_BIT, imageBytes);
    }

    // ---- The frame loop ----------------------------------------------------------------------
    for (uint32_t frameIndex = 0; frameIndex < kFrames; ++frameIndex) {
        PerFrame& f = frames[frameIndex % kFramesInFlight];
        VK(vkWaitForFences(device, 1, &f.fence, VK_TRUE, UINT64_MAX));
        VK(vkResetFences(device, 1, &f.fence));
        std::memcpy(f.uniforms.mapped, &uniforms, sizeof uniforms);

        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        VK(vkBeginCommandBuffer(f.cmd, &begin));
        const VkDeviceSize offset = 0;

        // The shadow map.
        VkClearValue clearDepth{};
        clearDepth.depthStencil = {1.0f, 0};
        VkRenderPassBeginInfo passBegin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        passBegin.renderPass = shadowPass;
        passBegin.framebuffer = shadowFramebuffer;
        passBegin.renderArea = {{0, 0}, kShadowExtent};
        passBegin.clearValueCount = 1;
        passBegin.pClearValues = &clearDepth;
        vkCmdBeginRenderPass(f.cmd, &passBegin, VK_SUBPASS_CONTENTS_INLINE);
        VkViewport viewport{0, 0, float(kShadowMapSize), float(kShadowMapSize), 0, 1};
        vkCmdSetViewport(f.cmd, 0, 1, &viewport);
        vkCmdSetScissor(f.cmd, 0, 1, &passBegin.renderArea);
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, shadowPipeline);
        vkCmdBindDescriptorSets(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout, 0, 1,
                                &f.descriptors, 0, nullptr);
        vkCmdBindVertexBuffers(f.cmd, 0, 1, &vertexBuffer.buffer, &offset);
        vkCmdDraw(f.cmd, static_cast<uint32_t>(vertices.size()), 1, 0, 0);
        vkCmdEndRenderPass(f.cmd);

        // The scene, then the UI.
        std::array<VkClearValue, 2> clears{};
        clears[0].color = {{0.02f, 0.02f, 0.03f, 1.0f}};
        clears[1].depthStencil = {1.0f, 0};
        passBegin.renderPass = renderPass;
        passBegin.framebuffer = f.framebuffer;
        passBegin.renderArea = {{0, 0}, kExtent};
        passBegin.clearValueCount = static_cast<uint32_t>(clears.size());
        passBegin.pClearValues = clears.data();
        vkCmdBeginRenderPass(f.cmd, &passBegin, VK_SUBPASS_CONTENTS_INLINE);
        viewport = {0, 0, float(kExtent.width), float(kExtent.height), 0, 1};
        vkCmdSetViewport(f.cmd, 0, 1, &viewport);
        vkCmdSetScissor(f.cmd, 0, 1, &passBegin.renderArea);
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, scenePipeline);
        vkCmdBindDescriptorSets(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout, 0, 1,
                                &f.descriptors, 0, nullptr);
        vkCmdBindVertexBuffers(f.cmd, 0, 1, &vertexBuffer.buffer, &offset);
        vkCmdDraw(f.cmd, static_cast<uint32_t>(vertices.size()), 1, 0, 0);
#if LS_WITH_PLUGIN
        // Here: after the scene's render pass (the plugin reads its depth and blends into its
        // color with passes of its own, which cannot run inside a render pass), and before the UI
        // (not to be fogged) and tone mapping, were there one (the plugin adds linear light).
        vkCmdEndRenderPass(f.cmd);
        frame.color = {f.swapchainImage.image, kColorFormat, kExtent, kColorUsage,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        frame.color.finalLayout = frame.color.layout;
        lightShafts->record(f.cmd, frame);
        passBegin.renderPass = uiRenderPass;
        vkCmdBeginRenderPass(f.cmd, &passBegin, VK_SUBPASS_CONTENTS_INLINE);
#endif
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, uiPipeline);
        vkCmdDraw(f.cmd, 4, 1, 0, 0);
        vkCmdEndRenderPass(f.cmd);

        // "Present": copy the image out (the render pass left it in TRANSFER_SRC_OPTIMAL).
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {kExtent.width, kExtent.height, 1};
        vkCmdCopyImageToBuffer(f.cmd, f.swapchainImage.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               f.readback.buffer, 1, &region);
        VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toHost.buffer = f.readback.buffer;
        toHost.size = VK_WHOLE_SIZE;
        vkCmdPipelineBarrier(f.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                             0, nullptr, 1, &toHost, 0, nullptr);
        VK(vkEndCommandBuffer(f.cmd));
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &f.cmd;
        VK(vkQueueSubmit(queue, 1, &submit, f.fence));
    }
    VK(vkDeviceWaitIdle(device));

    const PerFrame& last = frames[(kFrames - 1) % kFramesInFlight];
    const auto* image = static_cast<const uint8_t*>(last.readback.mapped);
    if (!options.write.empty()) writePpm(options.write, image, kExtent);
    int failures = 0;

    // ---- Shutdown ----------------------------------------------------------------------------
#if LS_WITH_PLUGIN
    failures += shaft_checks::compare(image, options.baseline, frame);  // the test's checks
    lightShafts.reset();  // before the device; every frame it recorded has completed
    vkDestroyRenderPass(device, uiRenderPass, nullptr);
#endif
    for (PerFrame& f : frames) {
        vkDestroyFence(device, f.fence, nullptr);
        vkDestroyFramebuffer(device, f.framebuffer, nullptr);
        vulkanDevice.destroy(f.uniforms);
        vulkanDevice.destroy(f.readback);
        vulkanDevice.destroy(f.swapchainImage);
    }
    vkDestroyDescriptorPool(device, descriptorPool, nullptr);
    vkDestroyCommandPool(device, commandPool, nullptr);
    vulkanDevice.destroy(vertexBuffer);
    for (VkPipeline p : {scenePipeline, uiPipeline, shadowPipeline})
        vkDestroyPipeline(device, p, nullptr);
    vkDestroyPipelineLayout(device, pipelineLayout, nullptr);
    vkDestroyDescriptorSetLayout(device, setLayout, nullptr);
    vkDestroyRenderPass(device, renderPass, nullptr);
    vkDestroyFramebuffer(device, shadowFramebuffer, nullptr);
    vkDestroyRenderPass(device, shadowPass, nullptr);
    vkDestroySampler(device, shadowSampler, nullptr);
    vulkanDevice.destroy(shadowMap);
    vulkanDevice.destroy(depth);
    vkDestroyDevice(device, nullptr);
    destroyMessenger(instance, messenger, nullptr);
    vkDestroyInstance(instance, nullptr);
    if (gValidationMessages > 0)
        std::fprintf(stderr, "FAILED: %d validation message(s)\n", gValidationMessages);
    return failures == 0 && gValidationMessages == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string arg = argv[i];
        if (arg == "--write")
            options.write = argv[i + 1];
        else if (arg == "--baseline")
            options.baseline = argv[i + 1];
    }
    try {
        return run(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "FAILED: exception: %s\n", e.what());
    }
    return 1;
}
