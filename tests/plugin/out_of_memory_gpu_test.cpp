// Out of memory at every Vulkan creation and allocation a frame makes, in turn (rendergraph's fault
// points): each surfaces as one DeviceError naming the call, nothing is recorded into the engine's
// command buffer, nothing leaks (the binary's teardown checks the layer's leak report), and the
// next frame, with memory back, renders the same image as a plugin that never failed.
#include <memory>
#include <string>

#include "plugin_fixture.h"
#include "rendergraph/fault_injection.h"
#include "rendergraph/vk_error.h"

using namespace plugin_test;

namespace {

FrameSpec smallSpot() {
    FrameSpec s;
    s.screen = {24, 16};
    s.view = defaultView(s.screen);
    s.light = spotOverGrille();
    s.light.shadowMapSize = 32;
    s.medium = fog();
    return s;
}

lightscatter::Settings tinySettings() {
    lightscatter::Settings s = smallSettings({24, 16});
    s.shadowMapSize = 32;
    return s;
}

}  // namespace

class OutOfMemoryGpu : public PluginGpuTest {};

TEST_F(OutOfMemoryGpu, EveryFaultPointOfAFirstFrameFailsCleanlyAndTheNextFrameWorks) {
    TestFrame frame(dev(), smallSpot());
    const auto description = frame.description(lightscatter::Method::Epipolar,
                                               lightscatter::Profile::Custom, tinySettings());

    // A first frame on a fresh plugin, counting its fault points: textures, memory, pipelines, the
    // executor's own objects.
    std::vector<float> expected;
    uint64_t points = 0;
    {
        lightscatter::Plugin fresh(contextOf(dev()));
        frame.resetColor();
        const uint64_t before = rg::vulkanCreationCount();
        fresh.render(description);
        points = rg::vulkanCreationCount() - before;
        expected = frame.inscatter();
    }
    std::printf("a first epipolar frame passes %llu fault points\n",
                static_cast<unsigned long long>(points));
    ASSERT_GT(points, 20u);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = dev().queueFamily();
    VkCommandPool pool;
    RG_VK(vkCreateCommandPool(dev().device(), &poolInfo, nullptr, &pool));
    const std::shared_ptr<void> poolGuard(
        nullptr, [&](void*) { vkDestroyCommandPool(dev().device(), pool, nullptr); });
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd;
    RG_VK(vkAllocateCommandBuffers(dev().device(), &alloc, &cmd));

    int allocations = 0;
    for (uint64_t n = 1; n <= points; ++n) {
        lightscatter::Plugin plugin(contextOf(dev()));
        // Odd points through record() on an engine's command buffer, even ones through render().
        const bool viaRecord = n % 2 == 1;
        if (!viaRecord) frame.resetColor();
        rg::failNthVulkanCreation(n);
        std::string error;
        try {
            if (viaRecord) {
                VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
                RG_VK(vkBeginCommandBuffer(cmd, &begin));
                try {
                    plugin.record(cmd, description);
                } catch (...) {
                    // Nothing was recorded: the engine's empty command buffer submits cleanly.
                    RG_VK(vkEndCommandBuffer(cmd));
                    dev().submitAndWait(cmd);
                    throw;
                }
                RG_VK(vkEndCommandBuffer(cmd));
            } else {
                plugin.render(description);
            }
        } catch (const lightscatter::DeviceError& e) {
            error = e.what();
        }
        rg::failNthVulkanCreation(0);
        ASSERT_FALSE(error.empty())
            << "fault point " << n << " of " << points << " did not fail the frame";
        EXPECT_NE(error.find("VK_ERROR_OUT_OF_DEVICE_MEMORY"), std::string::npos) << error;
        // A failed allocation says what needed the memory, how much, and what the device has.
        if (error.find("vkAllocateMemory") != std::string::npos) {
            ++allocations;
            EXPECT_EQ(error.rfind("lightscatter: out of device memory: ", 0), 0u) << error;
            EXPECT_NE(error.find(" needs "), std::string::npos) << error;
            EXPECT_NE(error.find("; the device has "), std::string::npos) << error;
        }
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
        EXPECT_EQ(error.rfind("lightscatter: ", 0), 0u) << error;

        frame.resetColor();
        plugin.render(description);
        EXPECT_EQ(frame.inscatter(), expected)
            << "the frame after fault point " << n << " (" << error << ")";
        RG_VK(vkResetCommandBuffer(cmd, 0));
    }
    EXPECT_GT(allocations, 0) << "no fault point was a memory allocation";
}

TEST_F(OutOfMemoryGpu, AFailedConstructionLeavesNothingBehind) {
    // Plugins on one device share its samplers and pipelines: this one names the loader's entry
    // points itself, which no other plugin of the binary does, so that it makes its device's
    // shared objects anew each time instead of finding another plugin's.
    lightscatter::PluginCreateInfo info;
    info.context = contextOf(dev());
    info.getInstanceProcAddr = vkGetInstanceProcAddr;
    const uint64_t before = rg::vulkanCreationCount();
    { lightscatter::Plugin probe(info); }
    const uint64_t points = rg::vulkanCreationCount() - before;
    ASSERT_GT(points, 0u);
    for (uint64_t n = 1; n <= points; ++n) {
        rg::failNthVulkanCreation(n);
        try {
            lightscatter::Plugin plugin(info);
            ADD_FAILURE() << "fault point " << n << " of the constructor did not fail it";
        } catch (const lightscatter::DeviceError& e) {
            EXPECT_NE(std::string(e.what()).find("VK_ERROR_OUT_OF_DEVICE_MEMORY"),
                      std::string::npos)
                << e.what();
        }
        rg::failNthVulkanCreation(0);
    }
}
