#include "device.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <utility>

#include "fault_injection.h"
#include "vk_error.h"

namespace rg {
namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

const char* typeName(VkPhysicalDeviceType t) {
    switch (t) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return "discrete GPU";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return "integrated GPU";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return "virtual GPU";
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return "CPU";
        default:
            return "other";
    }
}

int typeRank(VkPhysicalDeviceType t) {
    switch (t) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return 1;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return 3;
        default:
            return 4;
    }
}

bool hasExtension(const VulkanFunctions& vk_, VkPhysicalDevice pd, const char* name) {
    uint32_t n = 0;
    vk_.EnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> exts(n);
    vk_.EnumerateDeviceExtensionProperties(pd, nullptr, &n, exts.data());
    return std::any_of(exts.begin(), exts.end(), [&](const VkExtensionProperties& e) {
        return !std::strcmp(e.extensionName, name);
    });
}

bool hasInstanceExtension(const VulkanFunctions& vk_, const char* name) {
    uint32_t n = 0;
    vk_.EnumerateInstanceExtensionProperties(nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> exts(n);
    vk_.EnumerateInstanceExtensionProperties(nullptr, &n, exts.data());
    return std::any_of(exts.begin(), exts.end(), [&](const VkExtensionProperties& e) {
        return !std::strcmp(e.extensionName, name);
    });
}

bool hasLayer(const VulkanFunctions& vk_, const char* name) {
    uint32_t n = 0;
    vk_.EnumerateInstanceLayerProperties(&n, nullptr);
    std::vector<VkLayerProperties> layers(n);
    vk_.EnumerateInstanceLayerProperties(&n, layers.data());
    return std::any_of(layers.begin(), layers.end(),
                       [&](const VkLayerProperties& l) { return !std::strcmp(l.layerName, name); });
}

int graphicsComputeFamily(const VulkanFunctions& vk_, VkPhysicalDevice pd) {
    uint32_t n = 0;
    vk_.GetPhysicalDeviceQueueFamilyProperties(pd, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vk_.GetPhysicalDeviceQueueFamilyProperties(pd, &n, families.data());
    for (uint32_t i = 0; i < n; ++i) {
        const VkQueueFlags want = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & want) == want && families[i].timestampValidBits > 0)
            return static_cast<int>(i);
    }
    return -1;
}

// Why a device cannot run the runtime, or empty when it can.
std::string unsuitable(const VulkanFunctions& vk_, VkPhysicalDevice pd, bool swapchain) {
    VkPhysicalDeviceProperties props;
    vk_.GetPhysicalDeviceProperties(pd, &props);
    if (props.apiVersion < VK_API_VERSION_1_3) return "Vulkan 1.3 not supported";
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    f13.pNext = &f12;
    VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    f2.pNext = &f13;
    vk_.GetPhysicalDeviceFeatures2(pd, &f2);
    if (!f13.synchronization2) return "no synchronization2";
    if (!f13.dynamicRendering) return "no dynamicRendering";
    if (!f13.maintenance4) return "no maintenance4";
    if (!f12.separateDepthStencilLayouts) return "no separateDepthStencilLayouts";
    if (!f12.hostQueryReset) return "no hostQueryReset";
    if (!hasExtension(vk_, pd, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME))
        return "no VK_KHR_push_descriptor";
    if (swapchain && !hasExtension(vk_, pd, VK_KHR_SWAPCHAIN_EXTENSION_NAME))
        return "no VK_KHR_swapchain";
    if (graphicsComputeFamily(vk_, pd) < 0) return "no graphics+compute queue with timestamps";
    return {};
}

std::atomic<size_t> gMessagesInProcess{0};

}  // namespace

size_t validationMessagesInProcess() {
    return gMessagesInProcess.load();
}

VKAPI_ATTR VkBool32 VKAPI_CALL Device::onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT type,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                 void* user) {
    auto* self = static_cast<Device*>(user);
    if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
    if (!(type & (VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                  VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT)))
        return VK_FALSE;
    std::string text =
        (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error: " : "warning: ";
    if (data->pMessageIdName) text += std::string(data->pMessageIdName) + ": ";
    text += data->pMessage ? data->pMessage : "";
    {
        std::lock_guard lock(self->messagesMutex_);
        self->messages_.push_back(text);
    }
    ++gMessagesInProcess;
    if (self->echo_) std::cerr << "[vulkan validation] " << text << "\n";
    return VK_FALSE;
}

Device::Device(const DeviceOptions& options) : echo_(options.echoMessages) {
    allocator_ = options.allocator;
    try {
        vk_.loadGlobal(options.getInstanceProcAddr);
        createInstance(options);
        pickPhysicalDevice(options);
        createDevice(options);
    } catch (...) {
        destroy();
        throw;
    }
}

Device::Device(const ExternalDevice& external) : echo_(false) {
    if (!external.instance || !external.physical || !external.device || !external.queue)
        throw VulkanError(
            "an external device needs its instance, physical device, device and queue");
    owns_ = false;
    instance_ = external.instance;
    physical_ = external.physical;
    device_ = external.device;
    queue_ = external.queue;
    queueFamily_ = external.queueFamily;
    allocator_ = external.allocator;
    try {
        vk_.loadGlobal(external.getInstanceProcAddr);
        vk_.loadInstance(instance_);
        // Vulkan 1.0's call alone before the version is known: loadProperties() makes 1.1's.
        vk_.GetPhysicalDeviceProperties(physical_, &properties_);
        if (properties_.apiVersion < VK_API_VERSION_1_3)
            throw VulkanError("the engine's device '" + name() + "' offers Vulkan " +
                              std::to_string(VK_API_VERSION_MAJOR(properties_.apiVersion)) + "." +
                              std::to_string(VK_API_VERSION_MINOR(properties_.apiVersion)) +
                              ", not 1.3 (VkPhysicalDeviceProperties::apiVersion)");
        loadProperties();
        vk_.loadDevice(device_);
    } catch (...) {
        destroy();
        throw;
    }
}

Device::~Device() {
    destroy();
}

void Device::destroy() {
    if (!owns_) {
        device_ = VK_NULL_HANDLE;
        instance_ = VK_NULL_HANDLE;
        return;
    }
    if (device_) {
        vk_.DeviceWaitIdle(device_);
        if (oneShotPool_) vk_.DestroyCommandPool(device_, oneShotPool_, allocator_);
        vk_.DestroyDevice(device_, allocator_);
        device_ = VK_NULL_HANDLE;
    }
    if (messenger_) {
        vk_.DestroyDebugUtilsMessengerEXT(instance_, messenger_, allocator_);
        messenger_ = VK_NULL_HANDLE;
    }
    if (instance_) {
        vk_.DestroyInstance(instance_, allocator_);
        instance_ = VK_NULL_HANDLE;
    }
}

void Device::createInstance(const DeviceOptions& options) {
    validation_ = options.validation;
    const char* layerName = "VK_LAYER_KHRONOS_validation";
    if (validation_ && !hasLayer(vk_, layerName))
        throw VulkanError(
            "validation was requested but VK_LAYER_KHRONOS_validation is not installed (Debian "
            "package vulkan-validationlayers)");

    std::vector<const char*> extensions;
    for (const auto& e : options.instanceExtensions) extensions.push_back(e.c_str());
    debugUtils_ = hasInstanceExtension(vk_, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (debugUtils_) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (validation_) extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "lightscatter";
    app.pEngineName = "lightscatter-rendergraph";
    app.apiVersion = VK_API_VERSION_1_3;
    instanceApiVersion_ = app.apiVersion;

    VkDebugUtilsMessengerCreateInfoEXT messenger{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = &Device::onMessage;
    messenger.pUserData = this;

    const VkValidationFeatureEnableEXT syncFeature =
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = options.syncValidation ? 1 : 0;
    features.pEnabledValidationFeatures = &syncFeature;
    // Without its own handles the layer passes the driver's on, as an engine sees them: a handle
    // the driver reuses for a new object comes back as it is.
    const VkValidationFeatureDisableEXT uniqueHandles =
        VK_VALIDATION_FEATURE_DISABLE_UNIQUE_HANDLES_EXT;
    features.disabledValidationFeatureCount = options.uniqueHandles ? 0 : 1;
    features.pDisabledValidationFeatures = &uniqueHandles;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    if (validation_) {
        info.enabledLayerCount = 1;
        info.ppEnabledLayerNames = &layerName;
        features.pNext = debugUtils_ ? &messenger : nullptr;
        info.pNext = &features;
    } else if (debugUtils_) {
        info.pNext = &messenger;
    }
    const VkResult r = vk_.CreateInstance(&info, allocator_, &instance_);
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw VulkanError("no Vulkan 1.3 driver found (install mesa-vulkan-drivers for lavapipe)");
    check(r, "vkCreateInstance");
    vk_.loadInstance(instance_);
    if (!debugUtils_) {
        // The loader may answer for an extension the instance did not enable.
        vk_.CreateDebugUtilsMessengerEXT = nullptr;
        vk_.DestroyDebugUtilsMessengerEXT = nullptr;
        vk_.SetDebugUtilsObjectNameEXT = nullptr;
        vk_.CmdBeginDebugUtilsLabelEXT = nullptr;
        vk_.CmdEndDebugUtilsLabelEXT = nullptr;
    }
    if (vk_.CreateDebugUtilsMessengerEXT)
        RG_VK(vk_.CreateDebugUtilsMessengerEXT(instance_, &messenger, allocator_, &messenger_));
}

void Device::pickPhysicalDevice(const DeviceOptions& options) {
    uint32_t n = 0;
    RG_VK(vk_.EnumeratePhysicalDevices(instance_, &n, nullptr));
    std::vector<VkPhysicalDevice> all(n);
    RG_VK(vk_.EnumeratePhysicalDevices(instance_, &n, all.data()));

    std::string wanted = options.deviceName;
    if (wanted.empty())
        if (const char* env = std::getenv("LS_DEVICE")) wanted = env;

    std::string listing;
    VkPhysicalDevice best = VK_NULL_HANDLE;
    int bestRank = 1 << 30;
    for (VkPhysicalDevice pd : all) {
        VkPhysicalDeviceProperties p;
        vk_.GetPhysicalDeviceProperties(pd, &p);
        const std::string why = unsuitable(vk_, pd, options.swapchain);
        listing += std::string(listing.empty() ? " '" : "; '") + p.deviceName + "' (" +
                   typeName(p.deviceType) + ")" + (why.empty() ? "" : ": unsuitable, " + why);
        if (!why.empty()) continue;
        if (!wanted.empty()) {
            if (lower(p.deviceName).find(lower(wanted)) == std::string::npos) continue;
            best = pd;
            break;
        }
        if (typeRank(p.deviceType) < bestRank) {
            bestRank = typeRank(p.deviceType);
            best = pd;
        }
    }
    if (!best) {
        if (!wanted.empty())
            throw VulkanError("no suitable Vulkan device matches '" + wanted +
                              "' (from --device or LS_DEVICE); devices:" + listing);
        throw VulkanError(
            "no Vulkan 1.3 device with synchronization2, dynamic rendering and push "
            "descriptors; devices:" +
            (listing.empty() ? std::string(" none") : listing));
    }
    physical_ = best;
    queueFamily_ = static_cast<uint32_t>(graphicsComputeFamily(vk_, physical_));
    loadProperties();
    if (options.announce)
        std::cerr << "lightscatter: using Vulkan device '" << properties_.deviceName << "' ("
                  << typeName(properties_.deviceType) << ", driver " << driverName_ << ")"
                  << (validation_ ? ", validation on" : "") << "\n";
}

void Device::loadProperties() {
    vk_.GetPhysicalDeviceProperties(physical_, &properties_);
    vk_.GetPhysicalDeviceMemoryProperties(physical_, &memory_);
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceMaintenance3Properties maintenance3{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    driver.pNext = &maintenance3;
    VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    p2.pNext = &driver;
    vk_.GetPhysicalDeviceProperties2(physical_, &p2);
    maxAllocation_ = maintenance3.maxMemoryAllocationSize;
    driverName_ = std::string(driver.driverName) + " " + driver.driverInfo;
    uint32_t n = 0;
    vk_.GetPhysicalDeviceQueueFamilyProperties(physical_, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vk_.GetPhysicalDeviceQueueFamilyProperties(physical_, &n, families.data());
    if (queueFamily_ >= n) throw VulkanError("queue family index out of range");
    timestampBits_ = families[queueFamily_].timestampValidBits;
}

// The pool of submitAndWait(record), for a device of the runtime's own (its host's uploads).
void Device::createOneShotPool() {
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool.queueFamilyIndex = queueFamily_;
    RG_VK(vk_.CreateCommandPool(device_, &pool, allocator_, &oneShotPool_));
    setName(oneShotPool_, VK_OBJECT_TYPE_COMMAND_POOL, "one-shot command pool");
}

void Device::createDevice(const DeviceOptions& options) {
    VkPhysicalDeviceFeatures supported;
    vk_.GetPhysicalDeviceFeatures(physical_, &supported);
    VkPhysicalDeviceVulkan12Features have12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan11Features have11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    have12.pNext = &have11;
    VkPhysicalDeviceFeatures2 have{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    have.pNext = &have12;
    vk_.GetPhysicalDeviceFeatures2(physical_, &have);

    // Kept (enabledFeatures()): a plugin on this device is told what was enabled.
    VkPhysicalDeviceVulkan13Features& f13 = enabled_.v13;
    f13.synchronization2 = VK_TRUE;
    f13.dynamicRendering = VK_TRUE;
    f13.maintenance4 = VK_TRUE;
    VkPhysicalDeviceVulkan12Features& f12 = enabled_.v12;
    f12.separateDepthStencilLayouts = VK_TRUE;
    f12.hostQueryReset = VK_TRUE;
    f12.shaderFloat16 = have12.shaderFloat16;
    f12.scalarBlockLayout = have12.scalarBlockLayout;
    f12.pNext = &f13;
    VkPhysicalDeviceVulkan11Features& f11 = enabled_.v11;
    f11.storageBuffer16BitAccess = have11.storageBuffer16BitAccess;
    f11.pNext = &f12;
    VkPhysicalDeviceFeatures2& features = enabled_.core;
    features.pNext = &f11;
    features.features.shaderStorageImageExtendedFormats =
        supported.shaderStorageImageExtendedFormats;
    features.features.shaderClipDistance = supported.shaderClipDistance;
    features.features.fragmentStoresAndAtomics = supported.fragmentStoresAndAtomics;
    features.features.shaderImageGatherExtended = supported.shaderImageGatherExtended;
    features.features.independentBlend = supported.independentBlend;
    features.features.samplerAnisotropy = supported.samplerAnisotropy;
    features.features.depthClamp = supported.depthClamp;
    features.features.fillModeNonSolid = supported.fillModeNonSolid;
    features.features.dualSrcBlend = supported.dualSrcBlend;

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = queueFamily_;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;

    std::vector<const char*> extensions{VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    if (options.swapchain) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &features;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    RG_VK(vk_.CreateDevice(physical_, &info, allocator_, &device_));
    vk_.loadDevice(device_);
    vk_.GetDeviceQueue(device_, queueFamily_, 0, &queue_);
    setName(queue_, VK_OBJECT_TYPE_QUEUE, "lightscatter queue");
    createOneShotPool();
}

uint32_t Device::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags props) const {
    for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & props) == props)
            return i;
    throw VulkanError("no memory type with the requested properties");
}

void Device::setName(VkObjectType type, uint64_t handle, const std::string& name) const {
    if (!vk_.SetDebugUtilsObjectNameEXT || !handle) return;
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name.c_str();
    vk_.SetDebugUtilsObjectNameEXT(device_, &info);
}

void Device::beginLabel(VkCommandBuffer cmd, const std::string& name) const {
    if (!vk_.CmdBeginDebugUtilsLabelEXT) return;
    VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
    label.pLabelName = name.c_str();
    vk_.CmdBeginDebugUtilsLabelEXT(cmd, &label);
}

void Device::endLabel(VkCommandBuffer cmd) const {
    if (vk_.CmdEndDebugUtilsLabelEXT) vk_.CmdEndDebugUtilsLabelEXT(cmd);
}

void Device::submitAndWait(const std::function<void(VkCommandBuffer)>& record) const {
    if (!oneShotPool_)
        throw VulkanError("submitAndWait(record) needs a device of the runtime's own");
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = oneShotPool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd;
    RG_VK_CREATE(vk_.AllocateCommandBuffers(device_, &alloc, &cmd));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    RG_VK(vk_.BeginCommandBuffer(cmd, &begin));
    record(cmd);
    RG_VK(vk_.EndCommandBuffer(cmd));
    submitAndWait(cmd);
    vk_.FreeCommandBuffers(device_, oneShotPool_, 1, &cmd);
}

void Device::submitAndWait(VkCommandBuffer cmd, VkFence fence) const {
    VkCommandBufferSubmitInfo cbInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cbInfo.commandBuffer = cmd;
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cbInfo;
    RG_VK(vk_.QueueSubmit2(queue_, 1, &submit, fence));
    if (!fence) {
        RG_VK(vk_.QueueWaitIdle(queue_));
        return;
    }
    RG_VK(vk_.WaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX));
    RG_VK(vk_.ResetFences(device_, 1, &fence));
}

std::vector<std::string> Device::takeMessages() {
    std::lock_guard lock(messagesMutex_);
    return std::exchange(messages_, {});
}

size_t Device::messageCount() const {
    std::lock_guard lock(messagesMutex_);
    return messages_.size();
}

}  // namespace rg
