// The Vulkan versions a context needs, without a GPU: a fake physical device (fake_vulkan.h)
// answers the plugin's Vulkan 1.0 queries and records every entry point asked for, so each test
// also sees that nothing beyond the versions' calls was made (issue #38: the plugin called
// vkGetPhysicalDeviceProperties2 on a Vulkan 1.0 instance).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "fake_vulkan.h"

namespace device_queries_test {

using Names = std::vector<std::string>;

bool says(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A context on the fake device with every feature the plugin needs enabled.
struct Context {
    lightscatter::DeviceFeatures features = lightscatter::requiredDeviceFeatures();
    lightscatter::PluginCreateInfo info;
    explicit Context(uint32_t apiVersion) {
        info.getInstanceProcAddr = fake_vulkan::getInstanceProcAddr();
        info.context = {fake_vulkan::instance(),
                        fake_vulkan::physicalDevice(),
                        fake_vulkan::logicalDevice(),
                        fake_vulkan::queue(),
                        0,
                        features.chain(),
                        apiVersion};
    }
    // The refusal, or "(accepted)".
    std::string refusal() {
        try {
            lightscatter::Plugin p(info);
        } catch (const lightscatter::InvalidInput& e) {
            return e.what();
        } catch (const lightscatter::DeviceError& e) {
            // Past every check: the fake gives none of what a device is made with.
            return "(accepted)";
        }
        return "(accepted)";
    }
};

}  // namespace device_queries_test

using namespace device_queries_test;

// context.apiVersion is the engine's word on its instance: below 1.3 (0 included) it is refused
// before any Vulkan call; a device below 1.3 is refused after Vulkan 1.0's
// vkGetPhysicalDeviceProperties alone, before the features are looked at.
TEST(DeviceQueries, AContextBelowVulkan13IsRefusedNamingTheVersion) {
    fake_vulkan::reset();
    const std::string zero = Context(0).refusal();
    EXPECT_TRUE(says(zero,
                     "lightscatter: context.apiVersion is 0: it must be the "
                     "VkApplicationInfo::apiVersion the instance was created with"))
        << zero;
    const std::string old = Context(VK_API_VERSION_1_0).refusal();
    EXPECT_TRUE(says(old,
                     "lightscatter: context.apiVersion is 1.0.0: the instance must be created "
                     "with VkApplicationInfo::apiVersion VK_API_VERSION_1_3 or later"))
        << old;
    EXPECT_TRUE(says(Context(VK_API_VERSION_1_2).refusal(), "context.apiVersion is 1.2.0"));
    EXPECT_EQ(fake_vulkan::device().asked, Names{}) << "no Vulkan call for the instance's version";

    fake_vulkan::device().apiVersion = VK_MAKE_API_VERSION(0, 1, 0, 2);
    Context device10(VK_API_VERSION_1_3);
    device10.features.vulkan13.maintenance4 = VK_FALSE;  // the version is named, not the feature
    device10.info.context.enabledFeatures = device10.features.chain();
    const std::string device = device10.refusal();
    EXPECT_EQ(device,
              "lightscatter: context.physicalDevice 'fake device' offers Vulkan 1.0.2 "
              "(VkPhysicalDeviceProperties::apiVersion): the plugin needs a device of Vulkan 1.3 "
              "or later");
    EXPECT_EQ(fake_vulkan::device().asked, Names{"vkGetPhysicalDeviceProperties"});

    fake_vulkan::device().apiVersion = VK_API_VERSION_1_3;
    EXPECT_EQ(Context(VK_API_VERSION_1_3).refusal(), "(accepted)");
    EXPECT_EQ(Context(VK_MAKE_API_VERSION(0, 1, 4, 0)).refusal(), "(accepted)");
}
