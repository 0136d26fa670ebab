// The device contract without a GPU: the feature chain the plugin hands out, the one it fills in
// for an engine (a chain, or core features and a pNext kept apart), and the refusal of a context
// before any Vulkan call beyond Vulkan 1.0's vkGetPhysicalDeviceProperties is made.
#include <gtest/gtest.h>

#include <string>

#include <lightscatter/lightscatter.h>
#include "device_features.h"  // plugin_api/src: what the passes are told of optional features
#include "fake_vulkan.h"

namespace {

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST(DeviceFeatures, TheChainTurnsOnWhatThePluginNeeds) {
    lightscatter::DeviceFeatures f = lightscatter::requiredDeviceFeatures();
    VkPhysicalDeviceFeatures2* chain = f.chain();
    ASSERT_EQ(chain, &f.core);
    EXPECT_EQ(f.core.pNext, &f.vulkan11);
    EXPECT_EQ(f.vulkan11.pNext, &f.vulkan12);
    EXPECT_EQ(f.vulkan12.pNext, &f.vulkan13);
    EXPECT_EQ(f.vulkan13.pNext, nullptr);
    EXPECT_TRUE(f.vulkan13.synchronization2);
    EXPECT_TRUE(f.vulkan13.dynamicRendering);
    EXPECT_TRUE(f.vulkan13.maintenance4);
    EXPECT_TRUE(f.vulkan12.separateDepthStencilLayouts);
    EXPECT_TRUE(f.vulkan12.hostQueryReset);
    EXPECT_TRUE(f.core.features.shaderStorageImageExtendedFormats);
    EXPECT_TRUE(f.core.features.shaderClipDistance);
    EXPECT_TRUE(f.core.features.fragmentStoresAndAtomics);
    EXPECT_FALSE(f.vulkan12.timelineSemaphore);  // nothing the plugin does not need
    EXPECT_FALSE(f.core.features.geometryShader);
    const auto extensions = lightscatter::requiredDeviceExtensions();
    ASSERT_EQ(extensions.size(), 1u);
    EXPECT_EQ(std::string(extensions[0]), VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME);
}

TEST(DeviceFeatures, ChainRelinksAfterACopy) {
    const lightscatter::DeviceFeatures original = lightscatter::requiredDeviceFeatures();
    lightscatter::DeviceFeatures copy = original;
    EXPECT_EQ(copy.chain()->pNext, &copy.vulkan11);
    EXPECT_EQ(copy.vulkan12.pNext, &copy.vulkan13);
}

TEST(DeviceFeatures, AnEnginesOwnChainIsCompleted) {
    // An engine's chain: core, its own 1.3 structure, a per-feature structure for 1.2's.
    VkPhysicalDeviceHostQueryResetFeatures reset{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_HOST_QUERY_RESET_FEATURES};
    VkPhysicalDeviceSeparateDepthStencilLayoutsFeatures layouts{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SEPARATE_DEPTH_STENCIL_LAYOUTS_FEATURES};
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 core{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    core.features.geometryShader = VK_TRUE;  // the engine's
    v13.shaderDemoteToHelperInvocation = VK_TRUE;
    core.pNext = &v13;
    v13.pNext = &layouts;
    layouts.pNext = &reset;
    lightscatter::enableRequiredDeviceFeatures(core);
    EXPECT_TRUE(core.features.geometryShader);
    EXPECT_TRUE(core.features.shaderStorageImageExtendedFormats);
    EXPECT_TRUE(core.features.shaderClipDistance);
    EXPECT_TRUE(core.features.fragmentStoresAndAtomics);
    EXPECT_TRUE(v13.shaderDemoteToHelperInvocation);
    EXPECT_TRUE(v13.synchronization2 && v13.dynamicRendering && v13.maintenance4);
    EXPECT_TRUE(layouts.separateDepthStencilLayouts);
    EXPECT_TRUE(reset.hostQueryReset);
    EXPECT_EQ(core.pNext, &v13);  // the chain itself is untouched
    EXPECT_EQ(reset.pNext, nullptr);
}

TEST(DeviceFeatures, AChainWithoutRoomIsRefusedAndLeftAlone) {
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceFeatures2 core{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    core.pNext = &v12;
    try {
        lightscatter::enableRequiredDeviceFeatures(core);
        ADD_FAILURE() << "a chain without 1.3 features was completed";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_TRUE(contains(
            e.what(), "VkPhysicalDeviceVulkan13Features or VkPhysicalDeviceMaintenance4Features"))
            << e.what();
    }
    EXPECT_FALSE(v12.hostQueryReset);  // nothing was changed
    EXPECT_FALSE(core.features.shaderStorageImageExtendedFormats);
}

// Refused before the plugin makes any Vulkan call but the device's version (Vulkan 1.0's
// vkGetPhysicalDeviceProperties, which the fake answers), so fake handles do.
TEST(DeviceFeatures, APluginOnADeviceWithoutAFeatureIsRefusedNamingIt) {
    fake_vulkan::reset();
    lightscatter::DeviceFeatures f = lightscatter::requiredDeviceFeatures();
    f.vulkan13.maintenance4 = VK_FALSE;
    f.vulkan12.hostQueryReset = VK_FALSE;
    lightscatter::PluginCreateInfo info;
    info.getInstanceProcAddr = fake_vulkan::getInstanceProcAddr();
    lightscatter::VulkanContext& c = info.context;
    c.instance = fake_vulkan::instance();
    c.physicalDevice = fake_vulkan::physicalDevice();
    c.device = fake_vulkan::logicalDevice();
    c.queue = fake_vulkan::queue();
    c.enabledFeatures = f.chain();
    c.apiVersion = VK_API_VERSION_1_3;
    try {
        lightscatter::Plugin p(info);
        ADD_FAILURE() << "accepted";
    } catch (const lightscatter::InvalidInput& e) {
        const std::string m = e.what();
        EXPECT_TRUE(contains(m, "context.enabledFeatures")) << m;
        EXPECT_TRUE(contains(m, "maintenance4 (VkPhysicalDeviceVulkan13Features")) << m;
        EXPECT_TRUE(contains(m, "hostQueryReset (VkPhysicalDeviceVulkan12Features")) << m;
        EXPECT_FALSE(contains(m, "synchronization2")) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
    // Per-feature structures count as well as the versioned ones: only what is still off is named.
    VkPhysicalDeviceMaintenance4Features m4{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES};
    VkPhysicalDeviceHostQueryResetFeatures reset{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_HOST_QUERY_RESET_FEATURES};
    m4.maintenance4 = VK_TRUE;
    reset.hostQueryReset = VK_TRUE;
    m4.pNext = &reset;
    f.vulkan13.pNext = &m4;
    f.vulkan13.dynamicRendering = VK_FALSE;
    c.enabledFeatures = f.chain();
    try {
        lightscatter::Plugin p(info);
        ADD_FAILURE() << "accepted";
    } catch (const lightscatter::InvalidInput& e) {
        const std::string m = e.what();
        EXPECT_TRUE(contains(m, "dynamicRendering")) << m;
        EXPECT_FALSE(contains(m, "maintenance4")) << m;
        EXPECT_FALSE(contains(m, "hostQueryReset")) << m;
    }
    c.enabledFeatures = nullptr;
    EXPECT_THROW(lightscatter::Plugin{info}, lightscatter::InvalidInput);
    EXPECT_EQ(fake_vulkan::device().called,
              std::vector<std::string>(3, "vkGetPhysicalDeviceProperties"));
}

// An engine whose framework takes VkPhysicalDeviceFeatures and a pNext apart (issue #38: it builds
// its own VkPhysicalDeviceFeatures2 inside device creation and lets it go): each of the plugin's
// features is turned on where the engine keeps it, and nothing else changes.
TEST(DeviceFeatures, CoreFeaturesAndAChainKeptApartAreMergedFieldByField) {
    VkPhysicalDeviceFeatures core{};
    core.geometryShader = VK_TRUE;  // the engine's own
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    v12.timelineSemaphore = VK_TRUE;  // the engine's own
    v12.pNext = &v13;
    lightscatter::mergeRequiredDeviceFeatures(core, &v12);
    EXPECT_TRUE(core.geometryShader);
    EXPECT_TRUE(core.shaderStorageImageExtendedFormats && core.shaderClipDistance &&
                core.fragmentStoresAndAtomics);
    EXPECT_FALSE(core.dualSrcBlend) << "optional: asked for only of a device that has it";
    EXPECT_FALSE(core.tessellationShader);
    EXPECT_TRUE(v12.timelineSemaphore);
    EXPECT_TRUE(v12.separateDepthStencilLayouts && v12.hostQueryReset);
    EXPECT_FALSE(v12.bufferDeviceAddress);
    EXPECT_TRUE(v13.synchronization2 && v13.dynamicRendering && v13.maintenance4);
    EXPECT_EQ(v12.pNext, &v13);
    EXPECT_EQ(v13.pNext, nullptr);
    // What the engine then hands the plugin: the same features and chain as one
    // VkPhysicalDeviceFeatures2, which lacks nothing.
    VkPhysicalDeviceFeatures2 enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    enabled.features = core;
    enabled.pNext = &v12;
    EXPECT_TRUE(lightscatter::detail::featuresOff(enabled, false).empty());
    // Per-feature structures take the features as the versioned ones do.
    VkPhysicalDeviceFeatures core2{};
    VkPhysicalDeviceMaintenance4Features m4{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES};
    VkPhysicalDeviceVulkan13Features v13b{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features v12b{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    m4.pNext = &v12b;
    v12b.pNext = &v13b;
    lightscatter::mergeRequiredDeviceFeatures(core2, &m4);
    EXPECT_TRUE(v13b.maintenance4);  // the versioned structure first, as Vulkan reads both
    EXPECT_TRUE(v12b.hostQueryReset);
}

TEST(DeviceFeatures, AMergeWithoutRoomIsRefusedAndChangesNothing) {
    VkPhysicalDeviceFeatures core{};
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    try {
        lightscatter::mergeRequiredDeviceFeatures(core, &v13);
        ADD_FAILURE() << "a chain without Vulkan 1.2's features was completed";
    } catch (const lightscatter::InvalidInput& e) {
        const std::string m = e.what();
        EXPECT_TRUE(contains(m,
                             "mergeRequiredDeviceFeatures: the chain holds no "
                             "VkPhysicalDeviceVulkan12Features or "
                             "VkPhysicalDeviceSeparateDepthStencilLayoutsFeatures"))
            << m;
        EXPECT_TRUE(contains(m, "(for hostQueryReset)")) << m;
        EXPECT_FALSE(contains(m, "synchronization2")) << m;
    }
    EXPECT_FALSE(core.shaderClipDistance);
    EXPECT_FALSE(v13.synchronization2);
    EXPECT_THROW(lightscatter::mergeRequiredDeviceFeatures(core, nullptr),
                 lightscatter::InvalidInput);
    EXPECT_FALSE(core.shaderClipDistance);
}

// What the passes may use: dualSrcBlend where the engine's chain turns it on, never required.
TEST(DeviceFeatures, TheEnabledChainSaysWhetherDualSourceBlendingMayBeUsed) {
    lightscatter::DeviceFeatures f = lightscatter::requiredDeviceFeatures();
    EXPECT_FALSE(lightscatter::detail::enabledCapabilities(*f.chain()).dualSourceBlend);
    EXPECT_TRUE(lightscatter::detail::featuresOff(*f.chain(), false).empty())
        << "required without it";
    f.core.features.dualSrcBlend = VK_TRUE;
    EXPECT_TRUE(lightscatter::detail::enabledCapabilities(*f.chain()).dualSourceBlend);
}
