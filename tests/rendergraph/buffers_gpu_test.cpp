// Transient buffers through the graph: a compute pass fills one, another squares it into a second,
// a transfer pass copies the result to an imported host buffer.
#include <cstring>

#include "fill_buffer_comp.h"
#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/executor.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/pipeline.h"
#include "square_buffer_comp.h"
#include "support/gpu_test.h"

using testing_support::GpuTest;

class BuffersGpu : public GpuTest {};

TEST_F(BuffersGpu, ComputeChainThroughTransientBuffers) {
    static constexpr uint32_t kCount = 1000;
    const VkDeviceSize bytes = kCount * sizeof(uint32_t);
    rg::HostBuffer host(dev(), bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "buffer test readback");
    std::memset(host.data(), 0, bytes);

    struct Pipes {
        rg::Pipeline fill, square;
    };
    auto pipes = std::make_shared<Pipes>();
    rg::RenderGraph g;
    rg::BufferRef a = g.createBuffer("values", {bytes});
    rg::BufferRef b = g.createBuffer("squares", {bytes});
    rg::BufferRef out = g.importBuffer("readback", host.asReadback());
    {
        auto p = g.addPass("fill", rg::PassType::Compute);
        a = p.storageBufferWrite(a);
        const rg::BufferRef target = a;
        p.execute([pipes, target](rg::PassContext& ctx) {
            if (!pipes->fill)
                pipes->fill = rg::Pipeline::compute(ctx.device(), "fill",
                                                    rg::spirv(ls_spirv::fill_buffer_comp),
                                                    {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}, 4);
            pipes->fill.bind(ctx.cmd());
            rg::DescriptorPush()
                .storageBuffer(0, ctx.buffer(target))
                .push(ctx.device(), ctx.cmd(), pipes->fill);
            pipes->fill.push(ctx.cmd(), kCount);
            vkCmdDispatch(ctx.cmd(), (kCount + 63) / 64, 1, 1);
        });
    }
    {
        auto p = g.addPass("square", rg::PassType::Compute);
        p.storageBufferRead(a);
        b = p.storageBufferWrite(b);
        const rg::BufferRef src = a, dst = b;
        p.execute([pipes, src, dst](rg::PassContext& ctx) {
            if (!pipes->square)
                pipes->square = rg::Pipeline::compute(ctx.device(), "square",
                                                      rg::spirv(ls_spirv::square_buffer_comp),
                                                      {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                                       {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                                                      4);
            pipes->square.bind(ctx.cmd());
            rg::DescriptorPush()
                .storageBuffer(0, ctx.buffer(src))
                .storageBuffer(1, ctx.buffer(dst))
                .push(ctx.device(), ctx.cmd(), pipes->square);
            pipes->square.push(ctx.cmd(), kCount);
            vkCmdDispatch(ctx.cmd(), (kCount + 63) / 64, 1, 1);
        });
    }
    {
        auto p = g.addPass("copy out", rg::PassType::Transfer);
        p.transferSrc(b);
        out = p.transferDst(out);
        const rg::BufferRef src = b, dst = out;
        p.execute([src, dst](rg::PassContext& ctx) {
            VkBufferCopy region{0, 0, bytes};
            vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(src), ctx.buffer(dst), 1, &region);
        });
    }
    const rg::VulkanDeviceCaps caps(dev());
    rg::GraphExecutor exec(dev(), g, rg::compile(g, caps));
    for (int frame = 0; frame < 2; ++frame) {
        exec.run();
        const auto* v = static_cast<const uint32_t*>(host.data());
        for (uint32_t i = 0; i < kCount; ++i) ASSERT_EQ(v[i], (i + 1) * (i + 1)) << "index " << i;
        std::memset(host.data(), 0, bytes);
    }
}
