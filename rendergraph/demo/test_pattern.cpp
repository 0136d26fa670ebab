#include "test_pattern.h"

#include <cstring>

#include "blur_comp.h"
#include "circle_mask_frag.h"
#include "copy_frag.h"
#include "fullscreen_vert.h"
#include "histogram_comp.h"
#include "pattern_comp.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/pipeline.h"
#include "rendergraph/vk_error.h"

namespace rg::demo {

struct TestPatternPipelines {
    explicit TestPatternPipelines(const Device& d) : device(d), samplers(d) {}
    const Device& device;
    Samplers samplers;
    Pipeline pattern, mask, copy, invert, blur, histogram;
};

namespace {

uint32_t groups(uint32_t n) {
    return (n + 7) / 8;
}

GraphicsPipelineDesc fullscreen(ShaderCode fragment, const PassContext& ctx) {
    GraphicsPipelineDesc d;
    d.vertex = spirv(ls_spirv::fullscreen_vert);
    d.fragment = fragment;
    d.formats = ctx.renderingFormats();
    return d;
}

}  // namespace

TestPatternHandles declareTestPattern(RenderGraph& graph, VkExtent2D size, VkFormat depthStencil,
                                      const ImportedBuffer& readback,
                                      std::shared_ptr<TestPatternPipelines> pipes) {
    graph.setScreenExtent(size);
    TestPatternHandles h;
    h.pattern = graph.createImage("pattern", ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    h.mask = graph.createImage("circle mask", ImageDesc::screen(depthStencil));
    h.composed = graph.createImage("composed", ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    h.display = graph.createImage("display", ImageDesc::screen(VK_FORMAT_R8G8B8A8_UNORM));
    h.luma = graph.createImage("luma", ImageDesc::screen(VK_FORMAT_R32_SFLOAT));
    h.readback = graph.importBuffer("readback", readback);

    {
        auto pass = graph.addPass("generate pattern", PassType::Compute);
        const ImageRef out = pass.storageWrite(h.pattern);
        pass.execute([pipes, out](PassContext& ctx) {
            if (!pipes->pattern)
                pipes->pattern = Pipeline::compute(ctx.device(), "generate pattern",
                                                   spirv(ls_spirv::pattern_comp),
                                                   {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}});
            pipes->pattern.bind(ctx.cmd());
            DescriptorPush()
                .storage(0, ctx.view(out))
                .push(ctx.device(), ctx.cmd(), pipes->pattern);
            const VkExtent2D e = ctx.extent(out);
            vkCmdDispatch(ctx.cmd(), groups(e.width), groups(e.height), 1);
        });
        h.pattern = out;
    }
    {
        auto pass = graph.addPass("mark circle in stencil", PassType::Graphics);
        const ImageRef out = pass.stencilWrite(h.mask, LoadOp::Clear, 0);
        pass.execute([pipes, size](PassContext& ctx) {
            if (!pipes->mask) {
                auto d = fullscreen(spirv(ls_spirv::circle_mask_frag), ctx);
                d.pushConstantBytes = 8;
                d.stencilTest = true;
                d.stencil = {VK_STENCIL_OP_KEEP,
                             VK_STENCIL_OP_REPLACE,
                             VK_STENCIL_OP_KEEP,
                             VK_COMPARE_OP_ALWAYS,
                             0xff,
                             0xff,
                             1};
                pipes->mask = Pipeline::graphics(ctx.device(), "mark circle in stencil", d);
            }
            pipes->mask.bind(ctx.cmd());
            vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
            const uint32_t push[2] = {size.width, size.height};
            pipes->mask.push(ctx.cmd(), push);
            vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
        });
        h.mask = out;
    }
    auto copyPass = [&](const char* name, bool invert, ImageRef target, LoadOp load) {
        auto pass = graph.addPass(name, PassType::Graphics);
        pass.sampled(h.pattern);
        if (invert) pass.stencilTest(h.mask);
        const ImageRef out = pass.colorAttachment(target, load);
        const ImageRef src = h.pattern;
        pass.execute([pipes, src, invert, name](PassContext& ctx) {
            Pipeline& p = invert ? pipes->invert : pipes->copy;
            if (!p) {
                auto d = fullscreen(spirv(ls_spirv::copy_frag), ctx);
                d.bindings = {
                    {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};
                d.specialization.set(0, invert);
                if (invert) {
                    d.stencilTest = true;
                    d.stencil = {VK_STENCIL_OP_KEEP,
                                 VK_STENCIL_OP_KEEP,
                                 VK_STENCIL_OP_KEEP,
                                 VK_COMPARE_OP_EQUAL,
                                 0xff,
                                 0,
                                 1};
                }
                p = Pipeline::graphics(ctx.device(), name, d);
            }
            p.bind(ctx.cmd());
            if (invert) vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
            DescriptorPush()
                .sampled(0, ctx.view(src), ctx.layout(src), pipes->samplers.nearest())
                .push(ctx.device(), ctx.cmd(), p);
            vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
        });
        return out;
    };
    h.composed = copyPass("copy pattern", false, h.composed, LoadOp::DontCare);
    h.composed = copyPass("invert inside circle", true, h.composed, LoadOp::Load);
    {
        auto pass = graph.addPass("blur to 8-bit", PassType::Compute);
        pass.sampled(h.composed);
        const ImageRef out = pass.storageWrite(h.display);
        const ImageRef src = h.composed;
        pass.execute([pipes, src, out](PassContext& ctx) {
            if (!pipes->blur)
                pipes->blur =
                    Pipeline::compute(ctx.device(), "blur to 8-bit", spirv(ls_spirv::blur_comp),
                                      {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                       {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}});
            pipes->blur.bind(ctx.cmd());
            DescriptorPush()
                .sampled(0, ctx.view(src), ctx.layout(src), pipes->samplers.nearest())
                .storage(1, ctx.view(out))
                .push(ctx.device(), ctx.cmd(), pipes->blur);
            const VkExtent2D e = ctx.extent(out);
            vkCmdDispatch(ctx.cmd(), groups(e.width), groups(e.height), 1);
        });
        h.display = out;
    }
    {
        auto pass = graph.addPass("luma for debugging", PassType::Compute);
        pass.sampled(h.composed);
        const ImageRef out = pass.storageWrite(h.luma);
        const ImageRef src = h.composed;
        pass.execute([pipes, src, out](PassContext& ctx) {
            if (!pipes->histogram)
                pipes->histogram =
                    Pipeline::compute(ctx.device(), "luma", spirv(ls_spirv::histogram_comp),
                                      {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                       {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}});
            pipes->histogram.bind(ctx.cmd());
            DescriptorPush()
                .sampled(0, ctx.view(src), ctx.layout(src), pipes->samplers.nearest())
                .storage(1, ctx.view(out))
                .push(ctx.device(), ctx.cmd(), pipes->histogram);
            const VkExtent2D e = ctx.extent(out);
            vkCmdDispatch(ctx.cmd(), groups(e.width), groups(e.height), 1);
        });
        h.luma = out;
    }
    {
        auto pass = graph.addPass("read back", PassType::Transfer);
        pass.transferSrc(h.display);
        const BufferRef out = pass.transferDst(h.readback);
        const ImageRef src = h.display;
        pass.execute([src, out, size](PassContext& ctx) {
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {size.width, size.height, 1};
            vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(src), ctx.layout(src), ctx.buffer(out), 1,
                                   &region);
        });
        h.readback = out;
    }
    return h;
}

TestPatternRenderer::TestPatternRenderer(const Device& device, VkExtent2D size)
    : readback_(device, VkDeviceSize{4} * size.width * size.height,
                VK_BUFFER_USAGE_TRANSFER_DST_BIT, "test pattern readback") {
    const VulkanDeviceCaps caps(device);
    depthStencil_ =
        firstSupported(caps, {VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT},
                       VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT);
    if (depthStencil_ == VK_FORMAT_UNDEFINED)
        throw VulkanError("the device has no depth-stencil format with stencil");
    pipelines_ = std::make_shared<TestPatternPipelines>(device);
    declareTestPattern(graph_, size, depthStencil_, readback_.asReadback(), pipelines_);
    executor_ = std::make_unique<GraphExecutor>(device, graph_, compile(graph_, caps));
}

TestPatternRenderer::~TestPatternRenderer() {
    executor_.reset();  // waits for the device before pipelines go
}

std::vector<uint8_t> TestPatternRenderer::render(FrameTimings* timings) {
    const FrameTimings t = executor_->run();
    if (timings) *timings = t;
    std::vector<uint8_t> pixels(readback_.size());
    std::memcpy(pixels.data(), readback_.data(), pixels.size());
    return pixels;
}

}  // namespace rg::demo
