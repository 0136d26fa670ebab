// The test-pattern graph on a real device: compute, stencil-only graphics, stencil-tested graphics,
// compute, transfer, through aliased memory; pixels checked against a CPU model of the passes.
#include <array>
#include <cmath>

#include "rendergraph/demo/test_pattern.h"
#include "support/gpu_test.h"

using testing_support::GpuTest;

namespace {

// CPU model of shaders/demo: pattern.glsl, copy.frag (inverted inside the circle), blur.comp.
std::array<float, 4> pattern(uint32_t x, uint32_t y, uint32_t w, uint32_t h) {
    const bool check = (((x >> 3) ^ (y >> 3)) & 1u) == 1u;
    return {(static_cast<float>(x) + 0.5f) / static_cast<float>(w),
            (static_cast<float>(y) + 0.5f) / static_cast<float>(h), check ? 0.75f : 0.25f, 1.0f};
}

bool inside(uint32_t x, uint32_t y, uint32_t w, uint32_t h) {
    const float dx = static_cast<float>(x) + 0.5f - static_cast<float>(w) * 0.5f;
    const float dy = static_cast<float>(y) + 0.5f - static_cast<float>(h) * 0.5f;
    const float r = 0.35f * static_cast<float>(std::min(w, h));
    return dx * dx + dy * dy < r * r;
}

std::array<float, 4> composed(int x, int y, uint32_t w, uint32_t h) {
    auto c = pattern(static_cast<uint32_t>(x), static_cast<uint32_t>(y), w, h);
    if (inside(static_cast<uint32_t>(x), static_cast<uint32_t>(y), w, h))
        c = {1.0f - c[0], 1.0f - c[1], 1.0f - c[2], 1.0f};
    return c;
}

}  // namespace

class TestPatternGpu : public GpuTest {};

TEST_F(TestPatternGpu, PixelsMatchTheCpuModelOverSeveralFrames) {
    const VkExtent2D size{61, 45};  // not a multiple of the 8x8 workgroups
    rg::demo::TestPatternRenderer renderer(dev(), size);
    for (int frame = 0; frame < 3; ++frame) {
        rg::FrameTimings timings;
        const auto pixels = renderer.render(&timings);
        ASSERT_EQ(pixels.size(), size_t{4} * size.width * size.height);
        EXPECT_TRUE(timings.valid);
        EXPECT_EQ(timings.passes.size(), 6u);
        int bad = 0;
        for (uint32_t y = 0; y < size.height; ++y) {
            for (uint32_t x = 0; x < size.width; ++x) {
                std::array<float, 4> sum{};
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int sx = std::clamp(static_cast<int>(x) + dx, 0,
                                                  static_cast<int>(size.width) - 1);
                        const int sy = std::clamp(static_cast<int>(y) + dy, 0,
                                                  static_cast<int>(size.height) - 1);
                        const auto c = composed(sx, sy, size.width, size.height);
                        for (int k = 0; k < 4; ++k)
                            sum[static_cast<size_t>(k)] += c[static_cast<size_t>(k)];
                    }
                for (int k = 0; k < 4; ++k) {
                    const float expected = sum[static_cast<size_t>(k)] / 9.0f * 255.0f;
                    const float got =
                        pixels[(size_t{y} * size.width + x) * 4 + static_cast<size_t>(k)];
                    // float16 storage and 8-bit rounding: within two steps.
                    if (std::fabs(got - expected) > 2.0f && bad++ < 5)
                        ADD_FAILURE() << "pixel " << x << "," << y << " channel " << k << ": "
                                      << got << " vs " << expected;
                }
            }
        }
        EXPECT_EQ(bad, 0) << "frame " << frame;
    }
}

TEST_F(TestPatternGpu, TheBlurOutputReusesThePatternsMemory) {
    rg::demo::TestPatternRenderer renderer(dev(), {32, 32});
    const auto& c = renderer.compiled();
    const auto& g = renderer.graph();
    uint32_t pattern = rg::kInvalidIndex, display = rg::kInvalidIndex, luma = rg::kInvalidIndex;
    for (uint32_t i = 0; i < g.resources().size(); ++i) {
        if (g.resource(i).name == "pattern") pattern = i;
        if (g.resource(i).name == "display") display = i;
        if (g.resource(i).name == "luma") luma = i;
    }
    ASSERT_NE(pattern, rg::kInvalidIndex);
    ASSERT_NE(display, rg::kInvalidIndex);
    const auto& p = c.resources[pattern];
    const auto& d = c.resources[display];
    EXPECT_EQ(p.block, d.block);
    EXPECT_TRUE(p.offset < d.offset + d.memory.size && d.offset < p.offset + p.memory.size);
    EXPECT_LT(c.aliasedBytes, c.unaliasedBytes);
    EXPECT_FALSE(c.resources[luma].used);  // its pass was culled
    EXPECT_EQ(c.culled.size(), 1u);
    (void)renderer.render();
}
