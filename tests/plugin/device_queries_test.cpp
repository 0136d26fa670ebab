// What a physical device has and lacks, and the Vulkan versions a context needs, without a GPU: a
// fake physical device (fake_vulkan.h) answers the plugin's Vulkan 1.0 queries and records every
// entry point asked for, so each test also sees that nothing beyond the versions' calls was made
// (issue #38: the plugin called vkGetPhysicalDeviceProperties2 on a Vulkan 1.0 instance).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "fake_vulkan.h"

namespace device_queries_test {

using Names = std::vector<std::string>;

bool has(const Names& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

bool says(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

Names missing(uint32_t instanceApiVersion = VK_API_VERSION_1_3) {
    return lightscatter::missingDeviceFeatures(fake_vulkan::instance(),
                                               fake_vulkan::physicalDevice(), instanceApiVersion,
                                               fake_vulkan::getInstanceProcAddr());
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

TEST(DeviceQueries, ADeviceWithEverythingLacksNothing) {
    fake_vulkan::reset();
    EXPECT_EQ(missing(), Names{});
    EXPECT_TRUE(has(fake_vulkan::device().called, "vkGetPhysicalDeviceFeatures2"));
}

TEST(DeviceQueries, WhatTheDeviceLacksIsListedByName) {
    fake_vulkan::reset();
    fake_vulkan::Device& d = fake_vulkan::device();
    d.vulkan13.maintenance4 = VK_FALSE;
    d.vulkan12.hostQueryReset = VK_FALSE;
    d.core.fragmentStoresAndAtomics = VK_FALSE;
    d.core.dualSrcBlend = VK_FALSE;  // optional: never listed
    d.pushDescriptor = false;
    d.timestamps = false;
    EXPECT_EQ(missing(), (Names{"VK_KHR_push_descriptor", "maintenance4", "hostQueryReset",
                                "fragmentStoresAndAtomics",
                                "a queue family with graphics, compute and timestamps"}));
}

// Below 1.3 on either side only Vulkan 1.0's calls are made: the 1.2 and 1.3 features are neither
// asked for nor listed, and nothing is suggested that such a device could not enable.
TEST(DeviceQueries, BelowVulkan13OnlyVulkan10IsAskedAndTheVersionIsListed) {
    fake_vulkan::reset();
    fake_vulkan::device().apiVersion = VK_API_VERSION_1_0;
    fake_vulkan::device().vulkan13.maintenance4 = VK_FALSE;  // a 1.0 query cannot see it
    fake_vulkan::device().core.shaderClipDistance = VK_FALSE;
    EXPECT_EQ(missing(), (Names{"Vulkan 1.3 (the device offers 1.0.0)", "shaderClipDistance"}));
    EXPECT_FALSE(has(fake_vulkan::device().asked, "vkGetPhysicalDeviceFeatures2"));

    fake_vulkan::reset();
    EXPECT_EQ(missing(VK_API_VERSION_1_0),
              Names{"VkApplicationInfo::apiVersion 1.3 or later (the instance's is 1.0.0)"});
    EXPECT_FALSE(has(fake_vulkan::device().asked, "vkGetPhysicalDeviceFeatures2"));
    EXPECT_EQ(missing(0), Names{"VkApplicationInfo::apiVersion 1.3 or later (the instance's is 0, "
                                "which Vulkan reads as 1.0)"});
    EXPECT_EQ(missing(VK_API_VERSION_1_2),
              Names{"VkApplicationInfo::apiVersion 1.3 or later (the instance's is 1.2.0)"});
}

// dualSrcBlend is asked for where the device has it, and its absence refuses nothing.
TEST(DeviceQueries, OptionalFeaturesAreAskedForWhereTheDeviceHasThem) {
    fake_vulkan::reset();
    const lightscatter::DeviceFeatures with = lightscatter::requiredDeviceFeatures(
        fake_vulkan::instance(), fake_vulkan::physicalDevice(), fake_vulkan::getInstanceProcAddr());
    EXPECT_TRUE(with.core.features.dualSrcBlend);
    EXPECT_TRUE(with.vulkan13.maintenance4 && with.core.features.shaderClipDistance);
    EXPECT_FALSE(with.core.features.geometryShader) << "only what the plugin may use";
    VkPhysicalDeviceFeatures core{};
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    v12.pNext = &v13;
    lightscatter::mergeRequiredDeviceFeatures(core, &v12, fake_vulkan::instance(),
                                              fake_vulkan::physicalDevice(),
                                              fake_vulkan::getInstanceProcAddr());
    EXPECT_TRUE(core.dualSrcBlend);
    EXPECT_TRUE(core.shaderClipDistance && v12.hostQueryReset && v13.dynamicRendering);

    fake_vulkan::device().core.dualSrcBlend = VK_FALSE;
    const lightscatter::DeviceFeatures without = lightscatter::requiredDeviceFeatures(
        fake_vulkan::instance(), fake_vulkan::physicalDevice(), fake_vulkan::getInstanceProcAddr());
    EXPECT_FALSE(without.core.features.dualSrcBlend);
    EXPECT_TRUE(without.vulkan13.maintenance4);
    VkPhysicalDeviceFeatures core2{};
    lightscatter::mergeRequiredDeviceFeatures(core2, &v12, fake_vulkan::instance(),
                                              fake_vulkan::physicalDevice(),
                                              fake_vulkan::getInstanceProcAddr());
    EXPECT_FALSE(core2.dualSrcBlend);
    EXPECT_TRUE(core2.shaderClipDistance);
    // Only Vulkan 1.0's feature query, whatever the versions.
    EXPECT_FALSE(has(fake_vulkan::device().asked, "vkGetPhysicalDeviceFeatures2"));
    EXPECT_TRUE(has(fake_vulkan::device().called, "vkGetPhysicalDeviceFeatures"));
    EXPECT_EQ(missing(), Names{});
    // A device without it is accepted by the plugin.
    EXPECT_EQ(Context(VK_API_VERSION_1_3).refusal(), "(accepted)");
}

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
