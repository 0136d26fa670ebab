// A light's epipolar lines follow its screen rectangle (passes/epipolar/screen_share.h), without a
// device: the whole screen keeps the settings' sizes and seed 000's shrunk boundary to the bit; a
// smaller rectangle halves the slices by its perimeter and the samples by its diagonal, never
// below the settings' density, nor below the floor, nor off the march's grain; and a share near a
// step keeps the frame before's sizes until it has moved past the step by a margin.
#include <gtest/gtest.h>

#include "epipolar/screen_share.h"

namespace {

constexpr VkExtent2D kScreen{1920, 1080};

lightscatter::EpipolarSettings balanced() {
    lightscatter::EpipolarSettings s;
    s.slices = 1024;
    s.samplesPerSlice = 1024;
    s.initialSampleStep = 16;
    return s;
}

VkRect2D centred(uint32_t w, uint32_t h) {
    return {{static_cast<int32_t>((kScreen.width - w) / 2),
             static_cast<int32_t>((kScreen.height - h) / 2)},
            {w, h}};
}

TEST(EpipolarScreenShare, TheWholeScreenKeepsTheSettingsAndTheShrunkBoundary) {
    const ls::LineSizes sizes = ls::sizesForRect(balanced(), kScreen, {{0, 0}, kScreen}, nullptr);
    EXPECT_EQ(sizes.slices, 1024u);
    EXPECT_EQ(sizes.samples, 1024u);
    // The shaders' boundary before it came from the constants: -1 + 1/W and 1 - 1/W, in float.
    const glm::vec4 b = ls::lineBounds(kScreen, {{0, 0}, kScreen});
    EXPECT_EQ(b.x, -1.0f + 1.0f / 1920.0f);
    EXPECT_EQ(b.y, -1.0f + 1.0f / 1080.0f);
    EXPECT_EQ(b.z, 1.0f - 1.0f / 1920.0f);
    EXPECT_EQ(b.w, 1.0f - 1.0f / 1080.0f);
}

TEST(EpipolarScreenShare, ARectangleKeepsTheDensityOfItsBorderAndLines) {
    // A quarter of each side: the perimeter's and the diagonal's share are 1/4, two halvings.
    ls::LineSizes sizes = ls::sizesForRect(balanced(), kScreen, centred(480, 270), nullptr);
    EXPECT_EQ(sizes.slices, 256u);
    EXPECT_EQ(sizes.samples, 256u);
    // A little over a quarter: one halving only (the density never falls below the settings').
    sizes = ls::sizesForRect(balanced(), kScreen, centred(500, 290), nullptr);
    EXPECT_EQ(sizes.slices, 512u);
    EXPECT_EQ(sizes.samples, 512u);
    // A wide, flat strip: its perimeter is over half the screen's, its diagonal not.
    sizes = ls::sizesForRect(balanced(), kScreen, centred(1900, 40), nullptr);
    EXPECT_EQ(sizes.slices, 1024u);
    EXPECT_EQ(sizes.samples, 1024u / 1u);
    // A few pixels: the floor of 64 each.
    sizes = ls::sizesForRect(balanced(), kScreen, centred(3, 3), nullptr);
    EXPECT_EQ(sizes.slices, 64u);
    EXPECT_EQ(sizes.samples, 64u);
}

TEST(EpipolarScreenShare, SizesStayOnTheMarchsGrain) {
    // 1008 samples are a multiple of the initial step 16; 504 is not: no halving.
    lightscatter::EpipolarSettings s = balanced();
    s.samplesPerSlice = 1008;
    EXPECT_EQ(ls::sizesForRect(s, kScreen, centred(480, 270), nullptr).samples, 1008u);
    // 1000 slices halve to 500 (a multiple of 4), not to 250.
    s.slices = 1000;
    EXPECT_EQ(ls::sizesForRect(s, kScreen, centred(480, 270), nullptr).slices, 500u);
}

TEST(EpipolarScreenShare, AShareNearAStepKeepsTheFrameBeforesSizes) {
    const ls::LineSizes half{512, 512};
    // Just under a quarter: two halvings alone, but one from the frame before's until the share
    // is 15% under the step.
    EXPECT_EQ(ls::sizesForRect(balanced(), kScreen, centred(470, 264), &half), half);
    EXPECT_EQ(ls::sizesForRect(balanced(), kScreen, centred(400, 225), &half),
              (ls::LineSizes{256, 256}));
    // Growing takes effect at once.
    const ls::LineSizes quarter{256, 256};
    EXPECT_EQ(ls::sizesForRect(balanced(), kScreen, centred(500, 290), &quarter), half);
}

TEST(EpipolarScreenShare, ARectangleOfOnePixelIsWidenedToTwo) {
    const glm::vec4 b = ls::lineBounds(kScreen, {{1919, 500}, {1, 1}});
    EXPECT_LT(b.x, b.z);
    EXPECT_LT(b.y, b.w);
    EXPECT_FLOAT_EQ(b.z, 1.0f - 1.0f / 1920.0f);
}

}  // namespace
