// The poison debug option: a transient that a pass declares as written but leaves untouched reads
// back as the signalling pattern (NaN, all ones), in every frame, under synchronization validation.
#include <bit>
#include <cmath>
#include <cstring>

#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/executor.h"
#include "rendergraph/host_buffer.h"
#include "support/gpu_test.h"

using testing_support::GpuTest;

class PoisonGpu : public GpuTest {};

TEST_F(PoisonGpu, UnwrittenTransientsReadBackAsTheSignallingPattern) {
    constexpr uint32_t kSide = 8, kTexels = kSide * kSide;
    const VkDeviceSize floatBytes = kTexels * 4, uintBytes = kTexels * 4, bufferBytes = 256;
    rg::HostBuffer floats(dev(), floatBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                          "poison float readback");
    rg::HostBuffer uints(dev(), uintBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         "poison uint readback");
    rg::HostBuffer words(dev(), bufferBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         "poison buffer readback");

    rg::RenderGraph g;
    rg::ImageRef f =
        g.createImage("float image", rg::ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, kSide, kSide));
    rg::ImageRef u =
        g.createImage("uint image", rg::ImageDesc::absolute(VK_FORMAT_R16G16_UINT, kSide, kSide));
    rg::BufferRef b = g.createBuffer("buffer", {bufferBytes});
    rg::BufferRef outF = g.importBuffer("float readback", floats.asReadback());
    rg::BufferRef outU = g.importBuffer("uint readback", uints.asReadback());
    rg::BufferRef outB = g.importBuffer("buffer readback", words.asReadback());
    {
        // Declares writes and writes nothing: the bug the option exposes.
        auto p = g.addPass("forgetful writer", rg::PassType::Transfer);
        f = p.transferDst(f);
        u = p.transferDst(u);
        b = p.transferDst(b);
        p.execute([](rg::PassContext&) {});
    }
    {
        auto p = g.addPass("copy out", rg::PassType::Transfer);
        p.transferSrc(f);
        p.transferSrc(u);
        p.transferSrc(b);
        outF = p.transferDst(outF);
        outU = p.transferDst(outU);
        outB = p.transferDst(outB);
        const rg::ImageRef fi = f, ui = u;
        const rg::BufferRef bi = b, fo = outF, uo = outU, bo = outB;
        p.execute([=](rg::PassContext& ctx) {
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {kSide, kSide, 1};
            vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(fi), ctx.layout(fi), ctx.buffer(fo), 1,
                                   &region);
            vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(ui), ctx.layout(ui), ctx.buffer(uo), 1,
                                   &region);
            const VkBufferCopy copy{0, 0, bufferBytes};
            vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(bi), ctx.buffer(bo), 1, &copy);
        });
    }
    const rg::VulkanDeviceCaps caps(dev());
    rg::CompileOptions options;
    options.poisonTransients = true;
    rg::GraphExecutor exec(dev(), g, rg::compile(g, caps, options));
    for (int frame = 0; frame < 2; ++frame) {
        std::memset(floats.data(), 0, floatBytes);
        std::memset(uints.data(), 0, uintBytes);
        std::memset(words.data(), 0, bufferBytes);
        exec.run();
        const auto* fv = static_cast<const float*>(floats.data());
        const auto* uv = static_cast<const uint16_t*>(uints.data());
        const auto* bv = static_cast<const uint32_t*>(words.data());
        for (uint32_t i = 0; i < kTexels; ++i) ASSERT_TRUE(std::isnan(fv[i])) << "texel " << i;
        for (uint32_t i = 0; i < 2 * kTexels; ++i) ASSERT_EQ(uv[i], 0xffffu) << "channel " << i;
        for (uint32_t i = 0; i < bufferBytes / 4; ++i)
            ASSERT_EQ(bv[i], 0x7fc00000u) << "word " << i;
    }
}
