// The non-uniform medium's density m(x) and its optical depth along segments (docs/model.md,
// "Non-uniform media"): the closed forms against hand values and a brute-force midpoint rule.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "float64_model/box_crossings.h"
#include "float64_model/density.h"
#include "float64_model/density_kinks.h"
#include "float64_model/optical_depth.h"
#include "media_brute_force.h"

namespace ls::ref {
namespace {

using test::bruteOpticalDepth;

constexpr int kPanels = 400000;

Density heightOnly(double h0, double k, double d0 = 1.0) {
    Density d;
    d.base = d0;
    d.heightFog = HeightFog{h0, k};
    return d;
}

Density boxOnly(const FogBox& box) {
    Density d;
    d.base = 0.0;
    d.volumes.push_back(box);
    return d;
}

// A box turned about a tilted axis, so that no face is aligned with the world's axes.
FogBox rotatedBox(double fade) {
    FogBox b;
    b.center = {1.0, 2.0, -3.0};
    b.halfExtents = {1.5, 0.75, 2.0};
    const glm::dvec3 x = glm::normalize(glm::dvec3(1.0, 0.4, -0.3));
    const glm::dvec3 y = glm::normalize(glm::cross(glm::dvec3(0.2, 0.1, 1.0), x));
    b.axes = {x, y, glm::cross(x, y)};
    b.density = 2.5;
    b.fade = fade;
    return b;
}

double closedForm(const Density& d, const glm::dvec3& a, const glm::dvec3& b) {
    return opticalDepth(d, a, b);
}

void expectMatchesBruteForce(const Density& d, const glm::dvec3& a, const glm::dvec3& b,
                             double rel) {
    const double exact = closedForm(d, a, b);
    const double brute = bruteOpticalDepth(d, a, b, kPanels);
    EXPECT_TRUE(std::isfinite(exact));
    EXPECT_NEAR(exact, brute, rel * std::abs(brute) + 1e-300)
        << "segment (" << a.x << ", " << a.y << ", " << a.z << ") -> (" << b.x << ", " << b.y
        << ", " << b.z << ")";
    // Either way along the segment.
    EXPECT_NEAR(closedForm(d, b, a), exact, 1e-12 * std::abs(exact));
}

TEST(Density, IsDefinedAsTheModelSays) {
    Density d = heightOnly(2.0, 0.5, 3.0);
    EXPECT_EQ(d.at({0.0, 1.0, 0.0}), 3.0);  // below h0: full density
    EXPECT_EQ(d.at({0.0, 2.0, 0.0}), 3.0);
    EXPECT_DOUBLE_EQ(d.at({5.0, 6.0, 0.0}), 3.0 * std::exp(-0.5 * 4.0));
    FogBox box;
    box.center = {10.0, 0.0, 0.0};
    box.halfExtents = {2.0, 1.0, 3.0};
    box.density = 4.0;
    box.fade = 0.5;
    d.volumes.push_back(box);
    // At local (1.75, 0.25, 0): x is 0.25 inside its face, so its factor is 0.5; y and z are full.
    EXPECT_DOUBLE_EQ(d.at({11.75, 0.25, 0.0}), 3.0 + 4.0 * 0.5);
    // Two faded axes multiply: (0.25 / 0.5) (0.1 / 0.5).
    EXPECT_DOUBLE_EQ(d.at({11.75, 0.9, 0.0}), 3.0 + 4.0 * 0.5 * 0.2);
    EXPECT_EQ(d.at({12.5, 0.0, 0.0}), 3.0);  // outside
    EXPECT_EQ(d.maxDensity(), 7.0);
    EXPECT_FALSE(d.homogeneous());
    EXPECT_TRUE(Density{}.unit());
    Density twice;
    twice.base = 2.0;
    EXPECT_TRUE(twice.homogeneous());
    EXPECT_FALSE(twice.unit());
}

TEST(Density, FadeWiderThanTheBoxPeaksBelowOne) {
    FogBox b;
    b.halfExtents = {1.0, 2.0, 1.0};
    b.fade = 4.0;
    // The largest weight is at the centre, (1/4) (2/4) (1/4).
    EXPECT_DOUBLE_EQ(b.weight({0.0, 0.0, 0.0}), 0.25 * 0.5 * 0.25);
    EXPECT_DOUBLE_EQ(b.weight({0.5, 0.0, 0.0}), 0.125 * 0.5 * 0.25);
}

TEST(HeightOpticalDepth, ZeroFalloffIsTheLength) {
    const Density d = heightOnly(0.0, 0.0, 2.0);
    const glm::dvec3 a{0.0, -3.0, 0.0}, b{4.0, 9.0, 3.0};
    EXPECT_DOUBLE_EQ(closedForm(d, a, b), 2.0 * glm::length(b - a));
    expectMatchesBruteForce(d, a, b, 1e-12);
}

TEST(HeightOpticalDepth, SmallFalloffCrossingTheBase) {
    const Density d = heightOnly(1.0, 0.02);
    expectMatchesBruteForce(d, {0.0, -20.0, 0.0}, {30.0, 60.0, -10.0}, 1e-10);
    expectMatchesBruteForce(d, {0.0, 70.0, 0.0}, {30.0, -60.0, -10.0}, 1e-10);
    // A falloff so small that k |dy| l is 1e-12: G's limit, not 0/0.
    const Density tiny = heightOnly(0.0, 1e-14);
    expectMatchesBruteForce(tiny, {0.0, 5.0, 0.0}, {0.0, 105.0, 0.0}, 1e-12);
}

TEST(HeightOpticalDepth, HugeFalloffIsAThinLayer) {
    // k = 1e4: above the base the fog is gone within a millimetre.
    const Density d = heightOnly(0.5, 1e4);
    // Up through the base: 1 m below it, then 1 / (k dy) above.
    const glm::dvec3 a{0.0, -0.5, 0.0}, b{0.0, 1.5, 0.0};
    EXPECT_NEAR(closedForm(d, a, b), 1.0 + 1e-4, 1e-15);
    // The midpoint rule's own error on the layer is about (h k)^2 / 24 of its 1e-4.
    expectMatchesBruteForce(d, a, b, 1e-7);
    // Slanted, starting inside the layer just above the base.
    expectMatchesBruteForce(d, {0.0, 0.5001, 0.0}, {0.01, 0.5006, 0.0}, 1e-8);
    // Far above it the fog underflows to exactly 0 without a NaN.
    EXPECT_EQ(closedForm(d, {0.0, 100.0, 0.0}, {0.0, 200.0, 0.0}), 0.0);
    EXPECT_EQ(closedForm(d, {0.0, 100.0, 0.0}, {50.0, 100.0, 0.0}), 0.0);
}

TEST(HeightOpticalDepth, HorizontalSegments) {
    const Density d = heightOnly(2.0, 0.3);
    const glm::dvec3 a{-5.0, 0.0, 1.0}, b{7.0, 0.0, 4.0};
    const double l = glm::length(b - a);
    EXPECT_DOUBLE_EQ(closedForm(d, a, b), l);  // below
    const glm::dvec3 up{0.0, 5.0, 0.0};
    EXPECT_DOUBLE_EQ(closedForm(d, a + up, b + up), std::exp(-0.3 * 3.0) * l);  // above
    const glm::dvec3 at{0.0, 2.0, 0.0};
    EXPECT_DOUBLE_EQ(closedForm(d, a + at, b + at), l);  // on the base height
    expectMatchesBruteForce(d, a + up, b + up, 1e-12);
}

TEST(HeightOpticalDepth, FullyAboveOrBelow) {
    const Density d = heightOnly(-1.0, 0.7, 1.5);
    EXPECT_DOUBLE_EQ(closedForm(d, {0.0, -10.0, 0.0}, {3.0, -2.0, 1.0}),
                     1.5 * glm::length(glm::dvec3(3.0, 8.0, 1.0)));
    expectMatchesBruteForce(d, {0.0, 0.0, 0.0}, {3.0, 8.0, 1.0}, 1e-10);
    expectMatchesBruteForce(d, {3.0, 8.0, 1.0}, {0.0, 0.5, 0.0}, 1e-10);
}

TEST(BoxOpticalDepth, HardAxisAlignedIsTheChord) {
    FogBox b;
    b.center = {0.0, 1.0, 0.0};
    b.halfExtents = {1.0, 2.0, 3.0};
    b.density = 3.0;
    const Density d = boxOnly(b);
    EXPECT_DOUBLE_EQ(closedForm(d, {-5.0, 1.5, 0.0}, {5.0, 1.5, 0.0}), 3.0 * 2.0);
    // Starting inside the box: from its centre out through the +x face.
    EXPECT_DOUBLE_EQ(closedForm(d, {0.0, 1.0, 0.0}, {5.0, 1.0, 0.0}), 3.0 * 1.0);
    // Ending inside it.
    EXPECT_DOUBLE_EQ(closedForm(d, {0.0, 1.0, -10.0}, {0.0, 1.0, 2.0}), 3.0 * 5.0);
    // Missing it, and wholly inside it.
    EXPECT_EQ(closedForm(d, {-5.0, 3.5, 0.0}, {5.0, 3.5, 0.0}), 0.0);
    EXPECT_DOUBLE_EQ(closedForm(d, {-0.5, 0.0, 0.0}, {0.5, 0.0, 0.0}), 3.0);
    expectMatchesBruteForce(d, {-3.0, -2.0, -4.0}, {2.0, 3.0, 5.0}, 1e-9);
}

TEST(BoxOpticalDepth, HardRotated) {
    const Density d = boxOnly(rotatedBox(0.0));
    expectMatchesBruteForce(d, {-4.0, 0.0, -6.0}, {5.0, 4.0, 1.0}, 1e-9);
    expectMatchesBruteForce(d, {1.0, 2.0, -3.0}, {9.0, -5.0, 2.0}, 1e-9);  // from the centre
}

TEST(BoxOpticalDepth, FadedRotated) {
    const Density d = boxOnly(rotatedBox(0.4));
    expectMatchesBruteForce(d, {-4.0, 0.0, -6.0}, {5.0, 4.0, 1.0}, 1e-9);
    expectMatchesBruteForce(d, {1.2, 2.1, -2.9}, {9.0, -5.0, 2.0}, 1e-9);  // from inside
    expectMatchesBruteForce(d, {1.2, 2.1, -2.9}, {1.5, 2.0, -3.2}, 1e-9);  // wholly inside
}

TEST(BoxOpticalDepth, FadeWiderThanTheBox) {
    const Density d = boxOnly(rotatedBox(5.0));
    expectMatchesBruteForce(d, {-4.0, 0.0, -6.0}, {5.0, 4.0, 1.0}, 1e-9);
    expectMatchesBruteForce(d, {1.0, 2.0, -3.0}, {9.0, -5.0, 2.0}, 1e-9);
    // Along x through the centre the x factor is a triangle of height 1/4 on [-1, 1] (area 1/4),
    // and the others stay at their peaks 2/4 and 1/4.
    FogBox b;
    b.halfExtents = {1.0, 2.0, 1.0};
    b.fade = 4.0;
    EXPECT_DOUBLE_EQ(closedForm(boxOnly(b), {-3.0, 0.0, 0.0}, {3.0, 0.0, 0.0}), 0.25 * 0.5 * 0.25);
}

TEST(BoxOpticalDepth, DensityZeroAddsNothing) {
    FogBox b = rotatedBox(0.3);
    b.density = 0.0;
    Density d = heightOnly(0.0, 0.1);
    const glm::dvec3 a{-4.0, 0.0, -6.0}, e{5.0, 4.0, 1.0};
    const double without = closedForm(d, a, e);
    d.volumes.push_back(b);
    EXPECT_EQ(closedForm(d, a, e), without);
    EXPECT_EQ(closedForm(boxOnly(b), a, e), 0.0);
}

TEST(OpticalDepth, SumsTheBaseAndEveryVolume) {
    Density d = heightOnly(1.0, 0.25, 0.5);
    d.volumes.push_back(rotatedBox(0.0));
    FogBox second = rotatedBox(0.6);
    second.center = {2.0, 1.0, -2.0};  // overlapping the first
    second.density = 1.25;
    d.volumes.push_back(second);
    expectMatchesBruteForce(d, {-4.0, 0.0, -6.0}, {5.0, 4.0, 1.0}, 1e-9);
    expectMatchesBruteForce(d, {2.0, 1.0, -2.0}, {-6.0, 7.0, 3.0}, 1e-9);
    // Along a ray, a stretch [s0, s1] is the segment between its points.
    const Ray ray{{-4.0, 0.0, -6.0}, glm::normalize(glm::dvec3(9.0, 4.0, 7.0)), 12.0};
    EXPECT_NEAR(opticalDepth(d, ray, 3.0, 9.0),
                closedForm(d, ray.origin + 3.0 * ray.direction, ray.origin + 9.0 * ray.direction),
                1e-12);
    EXPECT_EQ(opticalDepth(d, ray, 5.0, 5.0), 0.0);
    EXPECT_EQ(opticalDepth(d, ray, 6.0, 5.0), 0.0);
}

TEST(MeanDecay, IsFiniteEverywhere) {
    EXPECT_EQ(meanDecay(0.0), 1.0);
    EXPECT_EQ(meanDecay(1e-300), 1.0);
    EXPECT_DOUBLE_EQ(meanDecay(1.0), 1.0 - std::exp(-1.0));
    EXPECT_DOUBLE_EQ(meanDecay(1e3), 1e-3);
    EXPECT_EQ(meanDecay(std::numeric_limits<double>::infinity()), 0.0);
}

TEST(DensityKinks, FacesFadePlanesAndTheBase) {
    FogBox b;
    b.center = {0.0, 0.0, 0.0};
    b.halfExtents = {2.0, 1.0, 1.0};
    b.fade = 0.5;
    // Along x through the centre: faces at -2 and 2, fade planes at -1.5 and 1.5 (from x = -10).
    const std::vector<double> kinks = boxWeightKinks(b, {-10.0, 0.2, 0.0}, {1.0, 0.0, 0.0});
    EXPECT_EQ(kinks, (std::vector<double>{8.0, 8.5, 11.5, 12.0}));
    // With the fade wider than the half extent, the centre plane instead.
    b.fade = 3.0;
    EXPECT_EQ(boxWeightKinks(b, {-10.0, 0.2, 0.0}, {1.0, 0.0, 0.0}),
              (std::vector<double>{8.0, 10.0, 12.0}));
    EXPECT_TRUE(boxWeightKinks(b, {-10.0, 5.0, 0.0}, {1.0, 0.0, 0.0}).empty());

    Density d = heightOnly(3.0, 0.0);
    d.volumes.push_back(b);
    const Ray ray{{-10.0, 0.2, 0.0}, glm::normalize(glm::dvec3(1.0, 0.0, 0.0)), 30.0};
    std::vector<double> got = densityFeatureDistances(d, ray);
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, (std::vector<double>{8.0, 10.0, 12.0}));  // horizontal: no base crossing
    const Ray up{{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 30.0};
    got = densityFeatureDistances(d, up);
    EXPECT_NE(std::find(got.begin(), got.end(), 3.0), got.end());
}

}  // namespace
}  // namespace ls::ref
