// The temporal mode's blue-noise tile (passes/froxels/froxel_blue_noise.h), without a device: every
// rank once, the same tile for the same seed, and blue: its low ranks spread apart and its small
// windows balanced, where white noise of the same values clumps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "froxels/froxel_blue_noise.h"

namespace {

constexpr uint32_t kSize = ls::kFroxelNoiseSize;

// The nearest two texels among those whose value is below `below`, on the torus (texels).
double nearestPair(const std::vector<float>& tile, float below) {
    std::vector<std::pair<int, int>> points;
    for (uint32_t p = 0; p < tile.size(); ++p)
        if (tile[p] < below) points.emplace_back(int(p % kSize), int(p / kSize));
    double nearest = 1e9;
    for (size_t i = 0; i < points.size(); ++i)
        for (size_t j = i + 1; j < points.size(); ++j) {
            int dx = std::abs(points[i].first - points[j].first);
            int dy = std::abs(points[i].second - points[j].second);
            dx = std::min(dx, int(kSize) - dx);
            dy = std::min(dy, int(kSize) - dy);
            nearest = std::min(nearest, std::sqrt(double(dx * dx + dy * dy)));
        }
    return nearest;
}

// The variance of the mean of every 3x3 window (wrapping) about 1/2.
double windowVariance(const std::vector<float>& tile) {
    double sum = 0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            double m = 0;
            for (uint32_t k = 0; k < 9; ++k)
                m += tile[((y + k / 3) % kSize) * kSize + (x + k % 3) % kSize];
            sum += (m / 9 - 0.5) * (m / 9 - 0.5);
        }
    return sum / (kSize * kSize);
}

std::vector<float> shuffled(std::vector<float> tile) {
    std::mt19937 rng(7);
    std::shuffle(tile.begin(), tile.end(), rng);
    return tile;
}

}  // namespace

TEST(FroxelBlueNoise, HoldsEveryRankOnce) {
    const std::vector<float>& tile = ls::froxelBlueNoise();
    ASSERT_EQ(tile.size(), size_t(kSize) * kSize);
    std::vector<float> sorted = tile;
    std::sort(sorted.begin(), sorted.end());
    for (size_t i = 0; i < sorted.size(); ++i)
        ASSERT_EQ(sorted[i], (float(i) + 0.5f) / float(sorted.size())) << "rank " << i;
}

TEST(FroxelBlueNoise, TheSeedAloneDecidesTheTile) {
    EXPECT_EQ(ls::voidAndClusterTile(16, 3), ls::voidAndClusterTile(16, 3));
    EXPECT_NE(ls::voidAndClusterTile(16, 3), ls::voidAndClusterTile(16, 4));
    EXPECT_EQ(ls::voidAndClusterTile(kSize, 1), ls::froxelBlueNoise());
}

// A tenth of the texels at density 0.1 lie about sqrt(10) = 3.2 texels apart; void and cluster
// keeps every pair at least 2 apart, and the same values shuffled (white noise) put some side by
// side. The 3x3 windows' means: white noise's vary as 1/12 / 9 = 0.0093; blue noise's far less.
TEST(FroxelBlueNoise, IsBlue) {
    const std::vector<float>& tile = ls::froxelBlueNoise();
    const std::vector<float> white = shuffled(tile);
    const double blueNearest = nearestPair(tile, 0.1f), whiteNearest = nearestPair(white, 0.1f);
    const double blueWindows = windowVariance(tile), whiteWindows = windowVariance(white);
    std::printf(
        "nearest low ranks: blue %.2f, white %.2f texels; 3x3 means' variance: blue %.5f, "
        "white %.5f\n",
        blueNearest, whiteNearest, blueWindows, whiteWindows);
    EXPECT_GE(blueNearest, 2.0);
    EXPECT_LT(whiteNearest, 2.0);
    EXPECT_LT(blueWindows, 0.25 * whiteWindows);
    EXPECT_GT(whiteWindows, 0.5 / 108.0);
}
