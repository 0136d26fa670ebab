// Engine-owned images imported into a graph: the graph renders into them, leaves them in the
// layout the engine asked for, and follows a new VkImage each frame (a swapchain's rotation).
#include <array>
#include <cmath>
#include <cstring>

#include "clear_color_frag.h"
#include "fullscreen_vert.h"
#include "read_layers_comp.h"
#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/executor.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/image_readback.h"
#include "rendergraph/owned_image.h"
#include "rendergraph/pipeline.h"
#include "rendergraph/vk_error.h"
#include "support/gpu_test.h"

using testing_support::GpuTest;

namespace {

// An engine's image: the runtime's own kind of owned image, with an engine's defaults.
struct EngineImage : rg::OwnedImage {
    EngineImage(const rg::Device& d, VkExtent2D e, const char* name,
                VkFormat format = VK_FORMAT_R8G8B8A8_UNORM,
                VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                          VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                uint32_t layers = 1, VkImageCreateFlags flags = 0)
        : rg::OwnedImage(d, format, e, usage, name, layers, flags) {}
};

// An engine's RGBA8 color target as the graph imports it: overwritten, then handed to a copy.
rg::ImportedImage engineColor(VkImage image, VkExtent2D size) {
    rg::ImportedImage d;
    d.image = image;
    d.format = VK_FORMAT_R8G8B8A8_UNORM;
    d.extent = size;
    d.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    d.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    d.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    d.finalStages = VK_PIPELINE_STAGE_2_COPY_BIT;
    d.finalAccess = VK_ACCESS_2_TRANSFER_READ_BIT;
    return d;
}

// The engine's own use after the graph: a copy from TRANSFER_SRC_OPTIMAL into `host`, read on the
// CPU.
void copyToHost(const rg::Device& dev, VkImage image, VkExtent2D size, rg::HostBuffer& host) {
    dev.submitAndWait([&](VkCommandBuffer cmd) {
        rg::recordReadback(dev, cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, size,
                           host.buffer());
    });
}

}  // namespace

class ImportsGpu : public GpuTest {};

TEST_F(ImportsGpu, RendersIntoEngineImagesAndLeavesThemInTheFinalLayout) {
    const VkExtent2D size{24, 16};
    EngineImage images[2] = {{dev(), size, "engine image 0"}, {dev(), size, "engine image 1"}};
    rg::HostBuffer host(dev(), 4 * size.width * size.height, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        "engine readback");

    auto describe = [&](VkImage img) { return engineColor(img, size); };
    auto pipeline = std::make_shared<rg::Pipeline>();
    auto colorValue = std::make_shared<std::array<float, 4>>();
    rg::RenderGraph g;
    rg::ImageRef target = g.importImage("engine color", describe(images[0].image()));
    {
        auto p = g.addPass("fill engine image", rg::PassType::Graphics);
        (void)p.colorAttachment(target, rg::LoadOp::DontCare);
        p.execute([pipeline, colorValue](rg::PassContext& ctx) {
            if (!*pipeline) {
                rg::GraphicsPipelineDesc d;
                d.vertex = rg::spirv(ls_spirv::fullscreen_vert);
                d.fragment = rg::spirv(ls_spirv::clear_color_frag);
                d.pushConstantBytes = 16;
                d.formats = ctx.renderingFormats();
                *pipeline = rg::Pipeline::graphics(ctx.device(), "fill engine image", d);
            }
            pipeline->bind(ctx.cmd());
            pipeline->push(ctx.cmd(), *colorValue);
            vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
        });
    }
    const rg::VulkanDeviceCaps caps(dev());
    rg::GraphExecutor exec(dev(), g, rg::compile(g, caps));

    for (int frame = 0; frame < 4; ++frame) {
        const EngineImage& img = images[frame % 2];
        g.updateImport(target, describe(img.image()));
        *colorValue = {static_cast<float>(frame) * 0.25f, 1.0f, 0.0f, 1.0f};
        exec.run();
        copyToHost(dev(), img.image(), size, host);
        const auto* px = static_cast<const uint8_t*>(host.data());
        const int expectedRed = static_cast<int>(std::lround(frame * 0.25 * 255.0));
        for (uint32_t i = 0; i < size.width * size.height; ++i) {
            ASSERT_NEAR(px[4 * i + 0], expectedRed, 1) << "frame " << frame << " pixel " << i;
            ASSERT_EQ(px[4 * i + 1], 255);
            ASSERT_EQ(px[4 * i + 2], 0);
        }
    }
}

// The engine's depth as a read-only depth attachment: a full-screen triangle at depth 0 is drawn
// where the engine's depth is farther (LESS) and nowhere where it is not, frame after frame, with
// the engine clearing the depth between frames (a write the graph's first barrier waits for).
TEST_F(ImportsGpu, EngineDepthIsAReadOnlyDepthAttachment) {
    const VkExtent2D size{16, 8};
    EngineImage color(dev(), size, "engine color");
    EngineImage depth(
        dev(), size, "engine depth", VK_FORMAT_D32_SFLOAT,
        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    rg::HostBuffer host(dev(), 4 * size.width * size.height, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        "engine readback");

    const rg::ImportedImage c = engineColor(color.image(), size);
    rg::ImportedImage d;
    d.image = depth.image();
    d.format = VK_FORMAT_D32_SFLOAT;
    d.extent = size;
    d.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;  // the engine's clear
    d.initialStages = VK_PIPELINE_STAGE_2_CLEAR_BIT;
    d.initialAccess = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    d.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;  // cleared again next frame
    d.finalStages = VK_PIPELINE_STAGE_2_CLEAR_BIT;
    d.finalAccess = VK_ACCESS_2_TRANSFER_WRITE_BIT;

    rg::RenderGraph g;
    rg::ImageRef target = g.importImage("engine color", c);
    rg::ImageRef engineDepth = g.importImage("engine depth", d);
    auto pipeline = std::make_shared<rg::Pipeline>();
    {
        auto p = g.addPass("depth-tested triangle", rg::PassType::Graphics);
        p.depthTest(engineDepth);
        (void)p.colorAttachment(target, rg::LoadOp::Clear);
        p.execute([pipeline, engineDepth](rg::PassContext& ctx) {
            if (!*pipeline) {
                rg::GraphicsPipelineDesc desc;
                desc.vertex = rg::spirv(ls_spirv::fullscreen_vert);  // depth 0
                desc.fragment = rg::spirv(ls_spirv::clear_color_frag);
                desc.pushConstantBytes = 16;
                desc.formats = ctx.renderingFormats();
                desc.depthTest = true;
                desc.depthWrite = false;
                desc.depthCompare = VK_COMPARE_OP_LESS;
                *pipeline = rg::Pipeline::graphics(ctx.device(), "depth-tested triangle", desc);
            }
            EXPECT_EQ(ctx.layout(engineDepth), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
            pipeline->bind(ctx.cmd());
            pipeline->push(ctx.cmd(), std::array<float, 4>{0.0f, 1.0f, 0.0f, 1.0f});
            vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
        });
    }
    const rg::VulkanDeviceCaps caps(dev());
    rg::GraphExecutor exec(dev(), g, rg::compile(g, caps));
    bool first = true;
    for (float clearDepth : {0.5f, 0.0f, 0.5f}) {
        dev().submitAndWait([&](VkCommandBuffer cmd) {
            VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
            b.srcStageMask = VK_PIPELINE_STAGE_2_CLEAR_BIT;
            b.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
            b.dstStageMask = VK_PIPELINE_STAGE_2_CLEAR_BIT;
            b.dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
            b.oldLayout = first ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            b.image = depth.image();
            b.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
            VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
            dep.imageMemoryBarrierCount = 1;
            dep.pImageMemoryBarriers = &b;
            vkCmdPipelineBarrier2(cmd, &dep);
            VkClearDepthStencilValue value{clearDepth, 0};
            VkImageSubresourceRange range{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
            vkCmdClearDepthStencilImage(cmd, depth.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                        &value, 1, &range);
        });
        first = false;
        exec.run();
        copyToHost(dev(), color.image(), size, host);
        const auto* px = static_cast<const uint8_t*>(host.data());
        const int green = clearDepth > 0.0f ? 255 : 0;  // depth 0 < 0.5 passes; 0 < 0 does not
        for (uint32_t i = 0; i < size.width * size.height; ++i)
            ASSERT_EQ(px[4 * i + 1], green) << "engine depth " << clearDepth << ", pixel " << i;
    }
}

// A six-layer depth image (a point light's cube shadow map: cube-compatible, or a plain 2D array)
// imported whole: the graph samples every layer through one 2D-array view, its first barrier moves
// all six layers out of the engine's layout and its last leaves all six in the final one. The
// engine then copies each layer out of TRANSFER_SRC_OPTIMAL, which the validation layer checks
// against the layout each layer is really in; a barrier covering layer 0 alone fails here.
TEST_F(ImportsGpu, SixLayerDepthImageIsTransitionedWhole) {
    constexpr uint32_t kLayers = 6;
    const VkExtent2D size{4, 4};
    for (const bool cube : {true, false}) {
        SCOPED_TRACE(cube ? "cube-compatible" : "2D array");
        const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        EngineImage depth(dev(), size, cube ? "engine cube depth" : "engine array depth",
                          VK_FORMAT_D32_SFLOAT, usage, kLayers,
                          cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0);
        rg::HostBuffer sampled(dev(), kLayers * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               "sampled layers");
        rg::HostBuffer copied(dev(), kLayers * size.width * size.height * sizeof(float),
                              VK_BUFFER_USAGE_TRANSFER_DST_BIT, "copied layers");
        const rg::Samplers samplers(dev());

        rg::ImportedImage d;
        d.image = depth.image();
        d.format = VK_FORMAT_D32_SFLOAT;
        d.extent = size;
        d.arrayLayers = kLayers;
        d.usage = usage;
        d.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;  // the engine's clears
        d.initialStages = VK_PIPELINE_STAGE_2_CLEAR_BIT;
        d.initialAccess = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        d.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;  // the engine's copy
        d.finalStages = VK_PIPELINE_STAGE_2_COPY_BIT;
        d.finalAccess = VK_ACCESS_2_TRANSFER_READ_BIT;

        auto pipeline = std::make_shared<rg::Pipeline>();
        rg::RenderGraph g;
        const rg::ImageRef layers = g.importImage("engine six-layer depth", d);
        rg::BufferRef values = g.createBuffer("layer values", {kLayers * sizeof(float)});
        rg::BufferRef out = g.importBuffer("readback", sampled.asReadback());
        {
            auto p = g.addPass("read every layer", rg::PassType::Compute);
            p.sampled(layers);
            values = p.storageBufferWrite(values);
            const rg::BufferRef target = values;
            const VkSampler nearest = samplers.nearest();
            p.execute([pipeline, layers, target, nearest](rg::PassContext& ctx) {
                if (!*pipeline)
                    *pipeline = rg::Pipeline::compute(
                        ctx.device(), "read every layer", rg::spirv(ls_spirv::read_layers_comp),
                        {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                         {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                        0);
                pipeline->bind(ctx.cmd());
                rg::DescriptorPush()
                    .sampled(0, ctx.view(layers, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(layers),
                             nearest)
                    .storageBuffer(1, ctx.buffer(target))
                    .push(ctx.device(), ctx.cmd(), *pipeline);
                vkCmdDispatch(ctx.cmd(), 1, 1, 1);
            });
        }
        {
            auto p = g.addPass("copy out", rg::PassType::Transfer);
            p.transferSrc(values);
            out = p.transferDst(out);
            const rg::BufferRef src = values, dst = out;
            p.execute([src, dst](rg::PassContext& ctx) {
                VkBufferCopy region{0, 0, kLayers * sizeof(float)};
                vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(src), ctx.buffer(dst), 1, &region);
            });
        }
        const rg::VulkanDeviceCaps caps(dev());
        rg::GraphExecutor exec(dev(), g, rg::compile(g, caps));
        for (int frame = 0; frame < 2; ++frame) {
            auto layerDepth = [&](uint32_t layer) {
                return 0.1f * static_cast<float>(layer + 1) + 0.05f * static_cast<float>(frame);
            };
            dev().submitAndWait([&](VkCommandBuffer cmd) {
                VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
                b.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
                b.srcAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
                b.dstStageMask = VK_PIPELINE_STAGE_2_CLEAR_BIT;
                b.dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
                b.oldLayout =
                    frame == 0 ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
                b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
                b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
                b.image = depth.image();
                b.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, kLayers};
                VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
                dep.imageMemoryBarrierCount = 1;
                dep.pImageMemoryBarriers = &b;
                vkCmdPipelineBarrier2(cmd, &dep);
                for (uint32_t layer = 0; layer < kLayers; ++layer) {
                    const VkClearDepthStencilValue value{layerDepth(layer), 0};
                    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, layer, 1};
                    vkCmdClearDepthStencilImage(cmd, depth.image(),
                                                VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &value, 1,
                                                &range);
                }
            });
            exec.run();
            const auto* v = static_cast<const float*>(sampled.data());
            for (uint32_t layer = 0; layer < kLayers; ++layer)
                EXPECT_FLOAT_EQ(v[layer], layerDepth(layer))
                    << "layer " << layer << ", frame " << frame;

            // The engine's next use, after the graph's last barrier: a copy of every layer.
            dev().submitAndWait([&](VkCommandBuffer cmd) {
                rg::recordReadback(dev(), cmd, depth.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                   size, copied.buffer(), VK_IMAGE_ASPECT_DEPTH_BIT, kLayers);
            });
            const auto* texels = static_cast<const float*>(copied.data());
            for (uint32_t layer = 0; layer < kLayers; ++layer)
                EXPECT_FLOAT_EQ(texels[layer * size.width * size.height], layerDepth(layer))
                    << "layer " << layer;
        }
    }
}
