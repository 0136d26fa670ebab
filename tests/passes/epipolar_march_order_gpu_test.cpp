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
#include <string>
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
    std::vector<uint32_t> texelOf;    // per sample k + samples * slice: x | y << 16
    std::vector<uint32_t> sampleOf;   // per texel x + width * y: k | slice << 16
    std::vector<uint32_t> slotOf;     // per texel: its slot of the march list, or ~0
    std::vector<uint32_t> marchedAt;  // per texel without a slot: the sample it marches
    bool list = false;                // the constants' march.z (marchesFromList)
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
    // `listCount`: the march list's count the marking and the march would read.
    Order evaluate(uint32_t slices, uint32_t samples, uint32_t step, uint32_t listCount = 0) {
        lightscatter::EpipolarSettings s;
        s.slices = slices;
        s.samplesPerSlice = samples;
        s.initialSampleStep = step;
        const ls::EpipolarConstants constants =
            ls::makeEpipolarConstants(s, 1024, false, false, glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f));
        const ls::EpipolarSizes sizes{slices, samples, ls::marchPhases(s)};
        Order o{slices, samples, sizes.marchPhases, sizes.marchExtent(), {}, {}, {}, {}, false};
        o.list = constants.march.z > 0.5f;
        const uint32_t count = slices * samples;
        EXPECT_EQ(o.extent.width * o.extent.height, count)
            << "the march's extent holds the samples";
        const VkDeviceSize bytes = VkDeviceSize(count) * sizeof(uint32_t);
        std::array<rg::HostBuffer, 4> host{
            rg::HostBuffer(dev(), bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "texel of sample"),
            rg::HostBuffer(dev(), bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "sample of texel"),
            rg::HostBuffer(dev(), bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "slot of texel"),
            rg::HostBuffer(dev(), bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "marched at texel")};
        for (auto& h : host) std::memset(h.data(), 0xee, bytes);

        auto pipe = std::make_shared<rg::Pipeline>();
        rg::RenderGraph g;
        rg::BufferRef ubo = g.createBuffer("epipolar constants", {sizeof(constants)});
        std::array<rg::BufferRef, 4> device, out;
        const char* names[] = {"texel of sample", "sample of texel", "slot of texel",
                               "marched at texel"};
        for (size_t i = 0; i < 4; ++i) {
            device[i] = g.createBuffer(std::string(names[i]) + " (device)", {bytes});
            out[i] = g.importBuffer(names[i], host[i].asReadback());
        }
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
            for (auto& d : device) d = p.storageBufferWrite(d);
            const rg::BufferRef u = ubo;
            const auto written = device;
            const std::array<uint32_t, 3> push{o.extent.width, o.extent.height, listCount};
            p.execute([pipe, u, written, push, count](rg::PassContext& ctx) {
                if (!*pipe)
                    *pipe = rg::Pipeline::compute(ctx.device(), "march order",
                                                  rg::spirv(ls_spirv::march_order_comp),
                                                  {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                                   {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                                   {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                                   {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                                   {5, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}},
                                                  sizeof(push));
                pipe->bind(ctx.cmd());
                rg::DescriptorPush descriptors;
                for (uint32_t i = 0; i < 4; ++i)
                    descriptors.storageBuffer(i, ctx.buffer(written[i]));
                descriptors.uniform(5, ctx.buffer(u)).push(ctx.device(), ctx.cmd(), *pipe);
                pipe->push(ctx.cmd(), push);
                vkCmdDispatch(ctx.cmd(), (count + 63) / 64, 1, 1);
            });
        }
        {
            auto p = g.addPass("copy out", rg::PassType::Transfer);
            for (auto& d : device) p.transferSrc(d);
            for (auto& h : out) h = p.transferDst(h);
            const auto from = device, to = out;
            p.execute([from, to, bytes](rg::PassContext& ctx) {
                const VkBufferCopy region{0, 0, bytes};
                for (size_t i = 0; i < 4; ++i)
                    vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(from[i]), ctx.buffer(to[i]), 1, &region);
            });
        }
        const rg::VulkanDeviceCaps caps(dev());
        rg::GraphExecutor exec(dev(), g, rg::compile(g, caps));
        exec.run();
        std::array<std::vector<uint32_t>*, 4> into{&o.texelOf, &o.sampleOf, &o.slotOf,
                                                   &o.marchedAt};
        for (size_t i = 0; i < 4; ++i) {
            const auto* v = static_cast<const uint32_t*>(host[i].data());
            into[i]->assign(v, v + count);
        }
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

// The march list (marchListSlot): with a list, the texels of the tiles take slots 0, 1, 2, ... of
// it, each slot one texel, 16 consecutive slots to one of the march's 4 x 4 blocks (what the list
// is for: a block of fragments full of samples to march); every other texel marches its own sample.
// A count past the list's capacity (an eighth of the tiles' samples) gives every texel its own
// sample, as without a list; so does a configuration without tiles.
TEST_F(EpipolarMarchOrderGpu, TheListsSlotsFillTheTilesBlockByBlock) {
    struct Config {
        uint32_t slices, samples, step;
        bool list;
    };
    const Config configs[] = {
        {1024, 1024, 16, true}, {1024, 512, 16, true},   {64, 1024, 32, true}, {128, 96, 8, true},
        {256, 128, 16, true},   {1020, 1024, 16, false}, {32, 16, 16, false},  {48, 64, 1, false}};
    for (const Config& c : configs) {
        const uint32_t phases = c.step, run = c.samples / phases - 1;
        const uint32_t tileSamples = c.list ? (phases - 1) * run * c.slices : 0;
        const uint32_t capacity = tileSamples / 8;
        for (uint32_t count : {0u, capacity, capacity + 1}) {
            const Order o = evaluate(c.slices, c.samples, c.step, count);
            SCOPED_TRACE(testing::Message() << c.slices << " slices, " << c.samples
                                            << " samples, step " << c.step << ", count " << count);
            EXPECT_EQ(o.list, c.list);
            const bool listed = c.list && count <= capacity;
            std::vector<uint32_t> texelOfSlot(tileSamples, ~0u);
            int problems = 0;
            for (uint32_t texel = 0; texel < o.slotOf.size() && problems < 5; ++texel) {
                const uint32_t k = o.sampleOf[texel] & 0xffffu;
                const bool tile = c.list && k % phases != 0 && k / phases != 0;
                const uint32_t slot = o.slotOf[texel];
                if (!(listed && tile)) {
                    if (slot != ~0u || o.marchedAt[texel] != o.sampleOf[texel]) {
                        ADD_FAILURE() << "texel " << texel << " (sample " << k
                                      << ") does not march its own sample";
                        ++problems;
                    }
                    continue;
                }
                if (slot >= tileSamples || texelOfSlot[slot] != ~0u) {
                    ADD_FAILURE() << "texel " << texel << " has slot " << slot << " of "
                                  << tileSamples << ", or another texel has it";
                    ++problems;
                    continue;
                }
                texelOfSlot[slot] = texel;
            }
            EXPECT_EQ(problems, 0);
            if (!listed) continue;
            // Every slot has its texel, and the slots 16 i .. 16 i + 15 share a 4 x 4 block.
            auto blockOf = [&](uint32_t texel) {
                return (texel % o.extent.width) / 4 + (texel / o.extent.width) / 4 * o.extent.width;
            };
            size_t missing = 0, split = 0;
            for (uint32_t slot = 0; slot < tileSamples; ++slot) {
                if (texelOfSlot[slot] == ~0u) {
                    ++missing;
                    continue;
                }
                split += blockOf(texelOfSlot[slot]) != blockOf(texelOfSlot[slot & ~15u]) ? 1 : 0;
            }
            EXPECT_EQ(missing, 0u);
            EXPECT_EQ(split, 0u);
        }
    }
}
