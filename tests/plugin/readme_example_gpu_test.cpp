// Runs docs/integration.md's example as an engine would: its own command buffer, its submit.
#include "plugin_fixture.h"
#include "readme_example.h"
#include "rendergraph/vk_error.h"
#include "support/projection.h"

using namespace plugin_test;

class ReadmeExampleGpu : public PluginGpuTest {};

TEST_F(ReadmeExampleGpu, RendersShaftsIntoTheEnginesColor) {
    const VkExtent2D extent{32, 24};
    const Scene scene = grilleScene();
    const View view = defaultView(extent);
    TestImage depth(dev(), VK_FORMAT_D32_SFLOAT, extent, VK_IMAGE_USAGE_SAMPLED_BIT,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "engine depth");
    depth.upload(renderDepth(scene, view, extent.width, extent.height));
    TestImage color(dev(), VK_FORMAT_R16G16B16A16_SFLOAT, extent, VK_IMAGE_USAGE_STORAGE_BIT,
                    VK_IMAGE_LAYOUT_GENERAL, "engine hdr color");
    color.clear(0.0f);
    lightscatter::Light light = spotOverGrille();
    light.position = {0.0f, 6.0f, 0.0f};
    const glm::mat4 lightMatrix = spotShadowMatrix(light, 0.5f, 30.0f);
    TestImage shadow(dev(), VK_FORMAT_D32_SFLOAT, {1024, 1024}, VK_IMAGE_USAGE_SAMPLED_BIT,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "engine shadow map");
    shadow.upload(renderShadowMap(scene, lightMatrix, 1024));

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.queueFamilyIndex = dev().queueFamily();
    VkCommandPool pool;
    RG_VK(vkCreateCommandPool(dev().device(), &poolInfo, nullptr, &pool));
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd;
    RG_VK(vkAllocateCommandBuffers(dev().device(), &alloc, &cmd));
    Engine engine;
    engine.context = {dev().instance(),
                      dev().physical(),
                      dev().device(),
                      dev().queue(),
                      dev().queueFamily(),
                      &dev().enabledFeatures(),
                      dev().instanceApiVersion()};
    engine.commandBuffer = cmd;
    engine.extent = extent;
    engine.depth = depth.image();
    engine.hdrColor = color.image();
    engine.shadowMap = shadow.image();
    engine.view = toMat4(view.view);
    engine.projection = toMat4(view.projection);
    engine.lightViewProjection = toMat4(lightMatrix);
    for (uint64_t frame = 1; frame <= 2; ++frame) {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        RG_VK(vkBeginCommandBuffer(cmd, &begin));
        const uint64_t number = recordLightShafts(engine);
        EXPECT_EQ(number, frame);
        RG_VK(vkEndCommandBuffer(cmd));
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmd;
        RG_VK(vkQueueSubmit(dev().queue(), 1, &submit, VK_NULL_HANDLE));
        RG_VK(vkQueueWaitIdle(dev().queue()));
        const lightscatter::FrameReport report = engine.lightShafts->report(number);
        EXPECT_EQ(report.frame, number);
        EXPECT_TRUE(report.timed);
        EXPECT_FALSE(report.passes.empty());
        EXPECT_GT(report.totalMilliseconds, 0.0);
        RG_VK(vkResetCommandPool(dev().device(), pool, 0));
    }
    engine.lightShafts.reset();
    vkDestroyCommandPool(dev().device(), pool, nullptr);

    const auto pixels = color.download();
    float brightest = 0;
    for (size_t i = 0; i < pixels.size(); i += 4) brightest = std::max(brightest, pixels[i]);
    EXPECT_GT(brightest, 0.0f);  // the engine's color was black; the shafts are in it now
}
