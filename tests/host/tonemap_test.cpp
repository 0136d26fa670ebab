// The PNGs' display encoding: bright stays bright at any magnitude, +Inf included (the ACES fit
// used to overflow from about 1e19 to NaN, which came out black).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

#include "tonemap.h"

namespace {

uint8_t red(float radiance, float exposure = 1.0f) {
    return host::toneMap({radiance, 0.0f, 0.0f, 1.0f}, exposure)[0];
}

}  // namespace

TEST(HostToneMap, VeryBrightPixelsStayWhite) {
    const float inf = std::numeric_limits<float>::infinity();
    for (float v : {8.0f, 1e4f, 1e19f, 1e30f, FLT_MAX, inf}) EXPECT_EQ(red(v), 255) << v;
    // Bright because of the exposure: exposure x radiance beyond 1e19, or overflowing to +Inf.
    EXPECT_EQ(red(1.0f, 1e30f), 255);
    EXPECT_EQ(red(1e20f, 1e20f), 255);
    EXPECT_EQ(red(FLT_MAX, FLT_MAX), 255);
}

TEST(HostToneMap, DarkAndMeaninglessPixelsAreBlack) {
    EXPECT_EQ(red(0.0f), 0);
    EXPECT_EQ(red(-5.0f), 0);
    EXPECT_EQ(red(-std::numeric_limits<float>::infinity()), 0);
    EXPECT_EQ(red(std::numeric_limits<float>::quiet_NaN()), 0);
}

TEST(HostToneMap, BrightnessNeverDecreasesWithRadiance) {
    uint8_t previous = 0;
    for (double v = 1e-4; v < 1e38; v *= 1.5) {
        const uint8_t now = red(float(v));
        EXPECT_GE(now, previous) << v;
        previous = now;
    }
    EXPECT_EQ(previous, 255);
    // Green and blue channels and alpha go the same way.
    const auto px =
        host::toneMap({0.0f, 1e25f, std::numeric_limits<float>::infinity(), 0.5f}, 1.0f);
    EXPECT_EQ(px[1], 255);
    EXPECT_EQ(px[2], 255);
    EXPECT_EQ(px[3], 255);
}
