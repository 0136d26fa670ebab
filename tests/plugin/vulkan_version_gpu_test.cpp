// The device contract of issue #38 on the test device (lavapipe), under validation: an engine's
// instance created for Vulkan 1.0 is refused with one line naming VkApplicationInfo::apiVersion and
// the version, and the validation layer reports nothing (the plugin made no call beyond Vulkan
// 1.0's: it used to call vkGetPhysicalDeviceProperties2, UNASSIGNED-API-Version-Violation); the
// queries of a physical device, and a device made the way an engine framework makes one, keeping
// the core features and the pNext chain apart.
#include <atomic>
#include <cstring>
#include <string>
#include <vector>

#include "plugin_fixture.h"
#include "rendergraph/vk_error.h"

namespace vv {

using Names = std::vector<std::string>;

bool says(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

std::atomic<int> gMessages{0};

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                         VkDebugUtilsMessageTypeFlagsEXT,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
        ++gMessages;
        ADD_FAILURE() << "validation: " << (data->pMessage ? data->pMessage : "");
    }
    return VK_FALSE;
}

// An engine's own instance, created for Vulkan 1.0 with the validation layer and synchronization
// validation, and a device on the test device's physical device made with Vulkan 1.0's
// pEnabledFeatures (the core features the plugin needs) and no extension.
class Vulkan10Engine {
  public:
    explicit Vulkan10Engine(const rg::Device& test) {
        const char* layer = "VK_LAYER_KHRONOS_validation";
        const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME,
                                    VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME};
        VkDebugUtilsMessengerCreateInfoEXT messenger{
            VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
        messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
        messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
        messenger.pfnUserCallback = &onMessage;
        const VkValidationFeatureEnableEXT sync =
            VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
        VkValidationFeaturesEXT validation{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
        validation.enabledValidationFeatureCount = 1;
        validation.pEnabledValidationFeatures = &sync;
        validation.pNext = &messenger;
        app.apiVersion = VK_API_VERSION_1_0;
        VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
        info.pNext = &validation;
        info.pApplicationInfo = &app;
        info.enabledLayerCount = 1;
        info.ppEnabledLayerNames = &layer;
        info.enabledExtensionCount = 2;
        info.ppEnabledExtensionNames = extensions;
        RG_VK(vkCreateInstance(&info, nullptr, &instance));
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        RG_VK(create(instance, &messenger, nullptr, &messenger_));

        // The test device's physical device, as this instance enumerates it.
        uint32_t n = 0;
        RG_VK(vkEnumeratePhysicalDevices(instance, &n, nullptr));
        std::vector<VkPhysicalDevice> all(n);
        RG_VK(vkEnumeratePhysicalDevices(instance, &n, all.data()));
        for (VkPhysicalDevice pd : all) {
            VkPhysicalDeviceProperties p;
            vkGetPhysicalDeviceProperties(pd, &p);
            if (test.name() == p.deviceName) physical = pd;
        }
        if (!physical) throw std::runtime_error("the test device is not among the instance's");
        family = test.queueFamily();
        const float priority = 1.0f;
        VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        queueInfo.queueFamilyIndex = family;
        queueInfo.queueCount = 1;
        queueInfo.pQueuePriorities = &priority;
        enabled.features = lightscatter::requiredDeviceFeatures().core.features;
        VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        deviceInfo.queueCreateInfoCount = 1;
        deviceInfo.pQueueCreateInfos = &queueInfo;
        deviceInfo.pEnabledFeatures = &enabled.features;
        RG_VK(vkCreateDevice(physical, &deviceInfo, nullptr, &device));
        vkGetDeviceQueue(device, family, 0, &queue);
    }
    ~Vulkan10Engine() {
        vkDestroyDevice(device, nullptr);
        destroyMessenger(instance, messenger_, nullptr);
        vkDestroyInstance(instance, nullptr);
    }
    Vulkan10Engine(const Vulkan10Engine&) = delete;
    Vulkan10Engine& operator=(const Vulkan10Engine&) = delete;

    lightscatter::VulkanContext context() const {
        return {instance, physical, device, queue, family, &enabled, app.apiVersion};
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t family = 0;
    VkPhysicalDeviceFeatures2 enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};

  private:
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    PFN_vkDestroyDebugUtilsMessengerEXT destroyMessenger = nullptr;
};

std::string refusal(const lightscatter::VulkanContext& context) {
    try {
        lightscatter::Plugin p(context);
    } catch (const lightscatter::InvalidInput& e) {
        return e.what();
    }
    return "(accepted)";
}

}  // namespace vv

class VulkanVersionGpu : public plugin_test::PluginGpuTest {};

TEST_F(VulkanVersionGpu, AVulkan10InstanceIsRefusedNamingItsVersionWithoutAValidationMessage) {
    vv::gMessages = 0;
    {
        vv::Vulkan10Engine engine(dev());
        const std::string m = vv::refusal(engine.context());
        EXPECT_TRUE(vv::says(m,
                             "lightscatter: context.apiVersion is 1.0.0: the instance must be "
                             "created with VkApplicationInfo::apiVersion VK_API_VERSION_1_3 or "
                             "later"))
            << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
        // Left unset: refused the same way (0 is also what Vulkan reads as 1.0).
        lightscatter::VulkanContext unset = engine.context();
        unset.apiVersion = 0;
        const std::string u = vv::refusal(unset);
        EXPECT_TRUE(vv::says(u, "context.apiVersion is 0")) << u;
        EXPECT_TRUE(vv::says(u, "VkApplicationInfo::apiVersion")) << u;
        // The query an engine picks a device with asks Vulkan 1.0 alone, and names the version.
        EXPECT_EQ(
            lightscatter::missingDeviceFeatures(engine.instance, engine.physical,
                                                engine.app.apiVersion),
            vv::Names{"VkApplicationInfo::apiVersion 1.3 or later (the instance's is 1.0.0)"});
    }
    EXPECT_EQ(vv::gMessages.load(), 0) << "the layer reported a call beyond the instance's version";
}

TEST_F(VulkanVersionGpu, TheTestDeviceLacksNothingAndIsAskedForDualSrcBlendWhereItHasIt) {
    EXPECT_EQ(lightscatter::missingDeviceFeatures(dev().instance(), dev().physical(),
                                                  dev().instanceApiVersion()),
              vv::Names{});
    VkPhysicalDeviceFeatures has;
    vkGetPhysicalDeviceFeatures(dev().physical(), &has);
    const lightscatter::DeviceFeatures f =
        lightscatter::requiredDeviceFeatures(dev().instance(), dev().physical());
    EXPECT_EQ(f.core.features.dualSrcBlend, has.dualSrcBlend);
    std::printf("%s: dualSrcBlend %s\n", dev().name().c_str(), has.dualSrcBlend ? "yes" : "no");
}

// An engine framework's device creation (issue #38): it is given VkPhysicalDeviceFeatures and a
// pNext chain, builds a VkPhysicalDeviceFeatures2 of its own inside device creation and lets it go.
// The engine merges the plugin's needs into its two parts, and tells the plugin what it enabled
// with a VkPhysicalDeviceFeatures2 of its own.
TEST_F(VulkanVersionGpu, ADeviceMadeFromCoreFeaturesAndAChainApartIsAccepted) {
    VkPhysicalDeviceFeatures core{};
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    v12.pNext = &v13;
    lightscatter::mergeRequiredDeviceFeatures(core, &v12, dev().instance(), dev().physical());
    const auto extensions = lightscatter::requiredDeviceExtensions();
    VkDevice device = VK_NULL_HANDLE;
    {
        // The framework's own, gone once the device is made.
        VkPhysicalDeviceFeatures2 inside{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        inside.features = core;
        inside.pNext = &v12;
        const float priority = 1.0f;
        VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        queue.queueFamilyIndex = dev().queueFamily();
        queue.queueCount = 1;
        queue.pQueuePriorities = &priority;
        VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        info.pNext = &inside;
        info.queueCreateInfoCount = 1;
        info.pQueueCreateInfos = &queue;
        info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
        info.ppEnabledExtensionNames = extensions.data();
        RG_VK(vkCreateDevice(dev().physical(), &info, nullptr, &device));
    }
    VkQueue q;
    vkGetDeviceQueue(device, dev().queueFamily(), 0, &q);
    VkPhysicalDeviceFeatures2 enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    enabled.features = core;
    enabled.pNext = &v12;
    EXPECT_EQ(vv::refusal({dev().instance(), dev().physical(), device, q, dev().queueFamily(),
                           &enabled, dev().instanceApiVersion()}),
              "(accepted)");
    vkDestroyDevice(device, nullptr);
}
