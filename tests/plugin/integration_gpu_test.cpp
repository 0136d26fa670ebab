// What an engine integrating the plugin runs into (issue #9): the device contract (features it must
// enable, checked at construction). Every refusal names the field, leaves the engine's images as
// they were and raises no validation message.
#include <cmath>
#include <cstring>
#include <functional>

#include "plugin_fixture.h"
#include "rendergraph/vk_error.h"

using namespace plugin_test;
using lightscatter::Method;

namespace {

FrameSpec spotFrame() {
    FrameSpec s;
    s.screen = {24, 16};
    s.view = defaultView(s.screen);  // a projection for 0.1 .. 50 m
    s.light = spotOverGrille();
    s.medium = fog();
    return s;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

class PluginIntegrationGpu : public PluginGpuTest {
protected:
    // Expects `change` to make the frame invalid with a message naming `field` (and containing
    // `rule`), and the engine's color to be untouched by the refused call.
    void expectRefused(const std::function<void(lightscatter::FrameDescription&)>& change,
                       const std::string& field, const std::string& rule = "") {
        TestFrame frame(dev(), spotFrame());
        const auto before = frame.color();
        auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                      smallSettings(frame.spec().screen));
        change(desc);
        try {
            plugin().render(desc);
            ADD_FAILURE() << "accepted; expected a refusal naming " << field;
        } catch (const lightscatter::InvalidInput& e) {
            EXPECT_TRUE(contains(e.what(), field)) << e.what();
            EXPECT_TRUE(contains(e.what(), rule)) << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos)
                << "one line: " << e.what();
        }
        EXPECT_EQ(frame.color(), before) << field;
    }

    std::vector<float> render(const std::function<void(lightscatter::FrameDescription&)>& change) {
        TestFrame frame(dev(), spotFrame());
        auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                      smallSettings(frame.spec().screen));
        change(desc);
        plugin().render(desc);
        return frame.color();
    }
};

// --- The device contract -------------------------------------------------------------------------

TEST_F(PluginIntegrationGpu, TheFeatureChainCreatesADeviceThePluginAccepts) {
    lightscatter::DeviceFeatures features = lightscatter::requiredDeviceFeatures();
    const auto extensions = lightscatter::requiredDeviceExtensions();
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = dev().queueFamily();
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = features.chain();
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkDevice device;
    RG_VK(vkCreateDevice(dev().physical(), &info, nullptr, &device));
    VkQueue q;
    vkGetDeviceQueue(device, dev().queueFamily(), 0, &q);
    EXPECT_NO_THROW(lightscatter::Plugin(
        {dev().instance(), dev().physical(), device, q, dev().queueFamily(), features.chain()}));
    vkDestroyDevice(device, nullptr);
}

// A device made without one feature: the plugin refuses it at construction, naming the feature,
// instead of validation reporting VUID-RuntimeSpirv-LocalSizeId-06434 (maintenance4) or
// VUID-vkResetQueryPool-None-02665 (hostQueryReset) once frames run, and nothing without it.
TEST_F(PluginIntegrationGpu, ADeviceWithoutARequiredFeatureIsRefusedNamingIt) {
    struct Case {
        const char* feature;
        std::function<void(lightscatter::DeviceFeatures&)> drop;
    };
    const Case cases[] = {
        {"maintenance4", [](auto& f) { f.vulkan13.maintenance4 = VK_FALSE; }},
        {"hostQueryReset", [](auto& f) { f.vulkan12.hostQueryReset = VK_FALSE; }},
        {"synchronization2", [](auto& f) { f.vulkan13.synchronization2 = VK_FALSE; }},
        {"shaderStorageImageExtendedFormats",
         [](auto& f) { f.core.features.shaderStorageImageExtendedFormats = VK_FALSE; }},
    };
    for (const Case& c : cases) {
        lightscatter::DeviceFeatures features = lightscatter::requiredDeviceFeatures();
        c.drop(features);
        const auto extensions = lightscatter::requiredDeviceExtensions();
        const float priority = 1.0f;
        VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        queue.queueFamilyIndex = dev().queueFamily();
        queue.queueCount = 1;
        queue.pQueuePriorities = &priority;
        VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        info.pNext = features.chain();
        info.queueCreateInfoCount = 1;
        info.pQueueCreateInfos = &queue;
        info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
        info.ppEnabledExtensionNames = extensions.data();
        VkDevice device;
        RG_VK(vkCreateDevice(dev().physical(), &info, nullptr, &device));
        VkQueue q;
        vkGetDeviceQueue(device, dev().queueFamily(), 0, &q);
        try {
            lightscatter::Plugin p({dev().instance(), dev().physical(), device, q,
                                    dev().queueFamily(), features.chain()});
            ADD_FAILURE() << "a device without " << c.feature << " was accepted";
        } catch (const lightscatter::InvalidInput& e) {
            EXPECT_TRUE(contains(e.what(), "context.enabledFeatures")) << e.what();
            EXPECT_TRUE(contains(e.what(), c.feature)) << e.what();
        }
        vkDestroyDevice(device, nullptr);
    }
}

TEST_F(PluginIntegrationGpu, AContextWithoutItsFeatureChainIsRefused) {
    const rg::Device& d = dev();
    try {
        lightscatter::Plugin p(
            {d.instance(), d.physical(), d.device(), d.queue(), d.queueFamily()});
        ADD_FAILURE() << "a context without enabledFeatures was accepted";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_TRUE(contains(e.what(), "context.enabledFeatures is null")) << e.what();
    }
    try {
        lightscatter::Plugin p({d.instance(), d.physical(), VK_NULL_HANDLE, d.queue(),
                                d.queueFamily(), &d.enabledFeatures()});
        ADD_FAILURE() << "a context without a device was accepted";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_TRUE(contains(e.what(), "context.device")) << e.what();
    }
}
