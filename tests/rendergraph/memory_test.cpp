// Transient memory: lifetimes x sizes placed so that resources alive together never overlap, and
// resources that are not alive together share memory.
#include <random>

#include "graph_test_util.h"
#include "rendergraph/block_occupants.h"
#include "rendergraph/memory_placement.h"

using namespace rg;

namespace {

// A chain t0 -> t1 -> t2 -> t3 of equal images: t0 dies when t2 is born, so they can share.
RenderGraph chain(ImageRef (&t)[4]) {
    RenderGraph g;
    for (int i = 0; i < 4; ++i)
        t[i] = g.createImage("t" + std::to_string(i),
                             ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, 256, 256));
    ImageRef prev;
    {
        auto p = g.addPass("p0", PassType::Compute);
        prev = p.storageWrite(t[0]);
    }
    for (int i = 1; i < 4; ++i) {
        auto p = g.addPass("p" + std::to_string(i), PassType::Compute);
        p.sampled(prev);
        prev = p.storageWrite(t[i]);
    }
    g.markOutput(prev);
    return g;
}

bool overlapInMemory(const ResourcePlan& a, const ResourcePlan& b) {
    return a.block == b.block && a.offset < b.offset + b.memory.size &&
           b.offset < a.offset + a.memory.size;
}

}  // namespace

TEST(Memory, ChainAliasesAndPeakIsLower) {
    ImageRef t[4];
    RenderGraph g = chain(t);
    const CompiledGraph c = compile(g, graph_test::caps());
    const VkDeviceSize one = c.resources[t[0].id].memory.size;
    EXPECT_EQ(c.unaliasedBytes, 4 * one);
    EXPECT_EQ(c.aliasedBytes, 2 * one);  // at most two are alive at once
    EXPECT_LT(c.aliasedBytes, c.unaliasedBytes);
    EXPECT_TRUE(overlapInMemory(c.resources[t[0].id], c.resources[t[2].id]));
    EXPECT_TRUE(overlapInMemory(c.resources[t[1].id], c.resources[t[3].id]));
    EXPECT_FALSE(overlapInMemory(c.resources[t[0].id], c.resources[t[1].id]));
}

TEST(Memory, AliasingOffGivesEveryResourceItsOwnMemory) {
    ImageRef t[4];
    RenderGraph g = chain(t);
    CompileOptions o;
    o.aliasing = false;
    const CompiledGraph c = compile(g, graph_test::caps(), o);
    EXPECT_EQ(c.aliasedBytes, c.unaliasedBytes);
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            EXPECT_FALSE(overlapInMemory(c.resources[t[i].id], c.resources[t[j].id]));
}

TEST(Memory, FirstUseOfAliasedResourceWaitsForThePreviousOccupant) {
    ImageRef t[4];
    RenderGraph g = chain(t);
    const CompiledGraph c = compile(g, graph_test::caps());
    // t2 is first used in p2 and takes t0's memory; t0 was last sampled by p1's compute shader.
    bool found = false;
    for (const auto& b : c.passes[2].barriers) {
        if (b.resource != t[2].id) continue;
        found = true;
        EXPECT_TRUE(b.firstUse);
        EXPECT_TRUE(b.aliased);
        EXPECT_EQ(b.oldLayout, VK_IMAGE_LAYOUT_UNDEFINED);
        EXPECT_NE(b.srcStages & VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0u);
    }
    EXPECT_TRUE(found);
}

TEST(Memory, RandomPlacementsKeepTheInvariant) {
    std::mt19937 rng(1234);  // 32-bit results, narrowed explicitly below
    for (int round = 0; round < 300; ++round) {
        std::vector<PlacementItem> items(2 + rng() % 40);
        const uint32_t passes = 1 + static_cast<uint32_t>(rng() % 20);
        for (auto& it : items) {
            it.first = static_cast<uint32_t>(rng() % passes);
            it.last = it.first + static_cast<uint32_t>(rng() % (passes - it.first));
            it.alignment = VkDeviceSize{1} << (rng() % 17);
            it.size = 1 + rng() % (1 << 20);
            it.linear = (rng() % 4) == 0;
            it.memoryType = static_cast<uint32_t>(rng() % 2);
        }
        const VkDeviceSize granularity = VkDeviceSize{1} << (rng() % 13);
        for (bool aliasing : {true, false}) {
            const PlacementResult r = placeResources(items, granularity, aliasing);
            const std::string problem = checkPlacement(items, r, granularity);
            ASSERT_TRUE(problem.empty()) << "round " << round << ": " << problem;
            // Nothing is larger than giving every resource its own aligned memory.
            VkDeviceSize sum = 0;
            for (const auto& it : items) sum += it.size + it.alignment + granularity;
            VkDeviceSize total = 0;
            for (const auto& b : r.blocks) total += b.size;
            EXPECT_LE(total, sum);
        }
    }
}

TEST(Memory, CheckPlacementCatchesAnOverlap) {
    std::vector<PlacementItem> items{{1000, 1, 0, 5, 0, false}, {1000, 1, 3, 8, 0, false}};
    PlacementResult r;
    r.placements = {{0, 0}, {0, 500}};
    r.blocks = {{0, 1500}};
    EXPECT_FALSE(checkPlacement(items, r, 1).empty());
    r.placements[1].offset = 1000;
    r.blocks[0].size = 2000;
    EXPECT_TRUE(checkPlacement(items, r, 1).empty());
}

TEST(Memory, GranularitySeparatesLinearFromOptimal) {
    // A buffer and an image alive together in one block must not share a granularity page.
    std::vector<PlacementItem> items{{100, 1, 0, 1, 0, true}, {100, 1, 0, 1, 0, false}};
    const PlacementResult r = placeResources(items, 4096, true);
    EXPECT_TRUE(checkPlacement(items, r, 4096).empty());
    const VkDeviceSize a = r.placements[0].offset, b = r.placements[1].offset;
    EXPECT_GE(a > b ? a - b : b - a, 4096u);
}

// The epipolar chain's lifetimes (balanced profile, sizes in MiB): placing the largest first puts
// the screen-sized stencil at offset 0 and stacks the long-lived samples textures above every
// short-lived one, 44 MiB; the most ever alive at once is 36 MiB (at the ray march), and another
// order reaches it.
TEST(Memory, PlacementTriesOrdersAndReachesTheLivePeak) {
    constexpr VkDeviceSize MiB = 1 << 20;
    const std::vector<PlacementItem> items{
        {16 * MiB, 1, 19, 20, 0, false},  // camera depth-stencil
        {8 * MiB, 1, 2, 17, 0, false},    // coordinates
        {8 * MiB, 1, 6, 17, 0, false},    // trees
        {8 * MiB, 1, 17, 18, 0, false},   // ray-marched samples
        {8 * MiB, 1, 18, 19, 0, false},   // all samples
        {4 * MiB, 1, 2, 19, 0, false},    // epipolar z
        {4 * MiB, 1, 2, 18, 0, false},    // epipolar stencil
        {4 * MiB, 1, 3, 18, 0, false},    // interpolation source
    };
    VkDeviceSize livePeak = 0;
    for (uint32_t pass = 0; pass <= 20; ++pass) {
        VkDeviceSize alive = 0;
        for (const auto& i : items)
            if (i.first <= pass && pass <= i.last) alive += i.size;
        livePeak = std::max(livePeak, alive);
    }
    EXPECT_EQ(livePeak, 36 * MiB);
    const PlacementResult r = placeResources(items, 1, true);
    EXPECT_TRUE(checkPlacement(items, r, 1).empty());
    ASSERT_EQ(r.blocks.size(), 1u);
    EXPECT_EQ(r.blocks[0].size, livePeak);
}

// The first-use barriers' source scope: the union over every resource sharing memory with the
// one first used, found by a segment tree (rendergraph/block_occupants.h), equals the union over
// all overlapping pairs taken one by one, and so does the count of overlapping resources.
TEST(Memory, BlockOccupantsAgreeWithEveryPairTakenOneByOne) {
    uint32_t seed = 7;
    auto next = [&](uint32_t n) {
        seed = seed * 1664525u + 1013904223u;
        return (seed >> 8) % n;
    };
    for (int round = 0; round < 50; ++round) {
        std::vector<rg::detail::BlockOccupants::Occupant> occupants;
        const uint32_t n = 1 + next(60);
        for (uint32_t i = 0; i < n; ++i) {
            const VkDeviceSize begin = next(1000), size = 1 + next(300);
            occupants.push_back({begin, begin + size, VkPipelineStageFlags2{1} << next(40),
                                 VkAccessFlags2{1} << next(40)});
        }
        const rg::detail::BlockOccupants tree(occupants);
        for (int q = 0; q < 40; ++q) {
            const VkDeviceSize begin = next(1200), end = begin + 1 + next(400);
            VkPipelineStageFlags2 stages = 0;
            VkAccessFlags2 access = 0;
            size_t count = 0;
            for (const auto& o : occupants)
                if (o.begin < end && begin < o.end) {
                    stages |= o.stages;
                    access |= o.access;
                    ++count;
                }
            const auto [treeStages, treeAccess] = tree.meeting(begin, end);
            ASSERT_EQ(treeStages, stages) << "round " << round << " query " << q;
            ASSERT_EQ(treeAccess, access) << "round " << round << " query " << q;
            ASSERT_EQ(tree.count(begin, end), count) << "round " << round << " query " << q;
        }
    }
}
