// The epipolar ray march's order (marchTexel and sampleOfMarchTexel in
// shaders/epipolar/epipolar_constants.glsl) as the passes' shaders evaluate it, on lavapipe with
// validation: for every configuration the chain can be given (the tiles of refined samples, and the
// block per phase they fall back to where the slices are not a multiple of 16 or a line's interval
// holds one sample), every sample has one texel within the march's extent
// (EpipolarSizes::marchExtent), no two share one, and the texel's sample is the sample. And what
// the tiles are for: a depth break that drifts one sample per slice across 16 slices, both sides
// marched, falls in about 9 of the march's 4 x 4 blocks, where a block per phase spread it over 17.
#include <array>
#include <cstring>
#include <set>
#include <vector>

#include "epipolar/epipolar_constants.h"
#include "epipolar/epipolar_nodes.h"
#include "march_order_comp.h"
#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/executor.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/pipeline.h"
#include "support/gpu_test.h"

using testing_support::GpuTest;

namespace {

struct Order {
    uint32_t slices, samples, phases;
    VkExtent2D extent;
    std::vector<uint32_t> texelOf;   // per sample k + samples * slice: x | y << 16
    std::vector<uint32_t> sampleOf;  // per texel x + width * y: k | slice << 16
};

// The march's 4 x 4 blocks that the samples on both sides of a break drifting one sample per
// slice across slices [0, 16) touch, averaged over where the break starts along the lines.
double meanBlocksOfADriftingBreak(const Order& o) {
    double sum = 0.0;
    int starts = 0;
    for (uint32_t k0 = o.phases + 1; k0 + 17 < o.samples; k0 += 3, ++starts) {
        std::set<uint32_t> blocks;
        for (uint32_t j = 0; j < 16; ++j)
            for (uint32_t k : {k0 + j, k0 + j + 1}) {
                const uint32_t t = o.texelOf[k + o.samples * j];
                blocks.insert(((t & 0xffffu) / 4) | ((t >> 16) / 4) << 16);
            }
        sum += static_cast<double>(blocks.size());
    }
    return starts > 0 ? sum / starts : 0.0;
}

}  // namespace

class EpipolarMarchOrderGpu : public GpuTest {
  protected:
    Order evaluate(uint32_t slices, uint32_t samples, uint32_t step) {
        lightscatter::EpipolarSettings s;
        s.slices = slices;
        s.samplesPerSlice = samples;
        s.initialSampleStep = step;
        const ls::EpipolarConstants constants =
            ls::makeEpipolarConstants(s, 1024, false, false, glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f));
        const ls::EpipolarSizes sizes{slices, samples, ls::marchPhases(s)};
        Order o{slices, samples, sizes.marchPhases, sizes.marchExtent(), {}, {}};
        const uint32_t count = slices * samples;
        EXPECT_EQ(o.extent.width * o.extent.height, count)
            << "the march's extent holds the samples";
        const VkDeviceSize bytes = VkDeviceSize(count) * sizeof(uint32_t);
        rg::HostBuffer texels(dev(), bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "texel of sample");
        rg::HostBuffer samplesOut(dev(), bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  "sample of texel");
        std::memset(texels.data(), 0xff, bytes);
        std::memset(samplesOut.data(), 0xff, bytes);

        auto pipe = std::make_shared<rg::Pipeline>();
        rg::RenderGraph g;
        rg::BufferRef ubo = g.createBuffer("epipolar constants", {sizeof(constants)});
        rg::BufferRef a = g.createBuffer("texel of sample (device)", {bytes});
        rg::BufferRef b = g.createBuffer("sample of texel (device)", {bytes});
        rg::BufferRef outA = g.importBuffer("texel of sample", texels.asReadback());
        rg::BufferRef outB = g.importBuffer("sample of texel", samplesOut.asReadback());
        {
            auto p = g.addPass("upload epipolar constants", rg::PassType::Transfer);
            ubo = p.transferDst(ubo);
            const rg::BufferRef dst = ubo;
            p.execute([dst, constants](rg::PassContext& ctx) {
                vkCmdUpdateBuffer(ctx.cmd(), ctx.buffer(dst), 0, sizeof(constants), &constants);
            });
        }
        {
            auto p = g.addPass("march order", rg::PassType::Compute);
            p.uniformBuffer(ubo);
            a = p.storageBufferWrite(a);
            b = p.storageBufferWrite(b);
            const rg::BufferRef u = ubo, ta = a, tb = b;
            const VkExtent2D extent = o.extent;
            p.execute([pipe, u, ta, tb, extent, count](rg::PassContext& ctx) {
                if (!*pipe)
                    *pipe = rg::Pipeline::compute(ctx.device(), "march order",
                                                  rg::spirv(ls_spirv::march_order_comp),
                                                  {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                                   {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                                   {5, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}},
                                                  8);
                pipe->bind(ctx.cmd());
                rg::DescriptorPush()
                    .storageBuffer(0, ctx.buffer(ta))
                    .storageBuffer(1, ctx.buffer(tb))
                    .uniform(5, ctx.buffer(u))
                    .push(ctx.device(), ctx.cmd(), *pipe);
                pipe->push(ctx.cmd(), std::array<uint32_t, 2>{extent.width, extent.height});
                vkCmdDispatch(ctx.cmd(), (count + 63) / 64, 1, 1);
            });
        }
        {
            auto p = g.addPass("copy out", rg::PassType::Transfer);
            p.transferSrc(a);
            p.transferSrc(b);
            outA = p.transferDst(outA);
            outB = p.transferDst(outB);
            const rg::BufferRef sa = a, sb = b, da = outA, db = outB;
            p.execute([sa, sb, da, db, bytes](rg::PassContext& ctx) {
                const VkBufferCopy region{0, 0, bytes};
                vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(sa), ctx.buffer(da), 1, &region);
                vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(sb), ctx.buffer(db), 1, &region);
            });
        }
        const rg::VulkanDeviceCaps caps(dev());
        rg::GraphExecutor exec(dev(), g, rg::compile(g, caps));
        exec.run();
        const auto* ta = static_cast<const uint32_t*>(texels.data());
        const auto* tb = static_cast<const uint32_t*>(samplesOut.data());
        o.texelOf.assign(ta, ta + count);
        o.sampleOf.assign(tb, tb + count);
        return o;
    }
};

TEST_F(EpipolarMarchOrderGpu, EverySampleHasOneTexelAndEveryTexelItsSample) {
    struct Config {
        uint32_t slices, samples, step;
    };
    // The profiles' sizes, a rectangle's halvings, slices of 4 but not 16 (a block per phase),
    // initial steps from 2 to 32, a line of one interval (no tiles), and no phases at all.
    const Config configs[] = {{1024, 1024, 16}, {2048, 1024, 16}, {1024, 512, 16}, {256, 128, 16},
                              {1020, 1024, 16}, {68, 256, 16},    {64, 1024, 32},  {128, 96, 8},
                              {64, 100, 2},     {128, 64, 4},     {16, 32, 16},    {32, 16, 16},
                              {64, 100, 16},    {48, 64, 1}};
    for (const Config& c : configs) {
        const Order o = evaluate(c.slices, c.samples, c.step);
        SCOPED_TRACE(testing::Message() << c.slices << " slices, " << c.samples << " samples, step "
                                        << c.step << " (" << o.phases << " phases)");
        std::vector<uint8_t> hit(o.extent.width * o.extent.height, 0);
        int problems = 0;
        for (uint32_t j = 0; j < o.slices && problems < 5; ++j)
            for (uint32_t k = 0; k < o.samples && problems < 5; ++k) {
                const uint32_t t = o.texelOf[k + o.samples * j];
                const uint32_t x = t & 0xffffu, y = t >> 16;
                if (x >= o.extent.width || y >= o.extent.height) {
                    ADD_FAILURE() << "sample (" << k << ", " << j << ") at texel (" << x << ", "
                                  << y << "), outside " << o.extent.width << "x" << o.extent.height;
                    ++problems;
                    continue;
                }
                const uint32_t texel = x + o.extent.width * y;
                if (hit[texel]++ != 0) {
                    ADD_FAILURE() << "texel (" << x << ", " << y << ") taken twice";
                    ++problems;
                }
                if (o.sampleOf[texel] != (k | j << 16)) {
                    ADD_FAILURE() << "sample (" << k << ", " << j << ") at (" << x << ", " << y
                                  << ") reads back (" << (o.sampleOf[texel] & 0xffffu) << ", "
                                  << (o.sampleOf[texel] >> 16) << ")";
                    ++problems;
                }
            }
        EXPECT_EQ(problems, 0);
    }
}

TEST_F(EpipolarMarchOrderGpu, ABreakDriftingAcrossSlicesSharesBlocks) {
    // Measured: 8.9 blocks (balanced's 1024 x 1024, step 16), 9.0 (high-performance's 512 samples),
    // 8.7 (step 32), 10.5 (step 8, 96 samples); a block per phase gives 17 in each.
    for (const auto [slices, samples, step] :
         {std::array<uint32_t, 3>{1024, 1024, 16}, {1024, 512, 16}, {64, 1024, 32}, {128, 96, 8}}) {
        const Order o = evaluate(slices, samples, step);
        EXPECT_LE(meanBlocksOfADriftingBreak(o), 11.0)
            << slices << " slices, " << samples << " samples, step " << step;
    }
    // Where the slices are not a multiple of 16 the refined samples keep a block per phase.
    EXPECT_GT(meanBlocksOfADriftingBreak(evaluate(1020, 1024, 16)), 16.0);
}
