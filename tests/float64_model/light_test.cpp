#include "float64_model/light.h"

#include <cmath>

#include <gtest/gtest.h>

#include "test_util.h"

namespace ls::ref {
namespace {

using test::near3;

Medium hazy() {
    Medium m;
    m.betaR = {1e-3, 2e-3, 4e-3};
    m.betaM = {1e-2, 1e-2, 1e-2};
    m.sigmaA = {0.0, 1e-3, 0.0};
    return m;
}

TEST(Light, ExtinctionSumsItsParts) {
    EXPECT_TRUE(near3(hazy().betaT(), {1.1e-2, 1.3e-2, 1.4e-2}, 1e-15));
}

TEST(Light, PointIrradianceFollowsModel) {
    Light l;
    l.type = Light::Point;
    l.position = {1.0, 2.0, 3.0};
    l.intensity = {10.0, 20.0, 30.0};
    l.r0 = 0.1;
    const glm::dvec3 p{4.0, 6.0, 3.0};  // r = 5
    const glm::dvec3 expected =
        l.intensity * glm::dvec3(std::exp(-0.011 * 5), std::exp(-0.013 * 5), std::exp(-0.014 * 5)) /
        (25.0 + 0.01);
    EXPECT_TRUE(near3(irradiance(l, hazy(), p), expected, 1e-14));
    // At the light itself the radius keeps it finite: I / r0^2.
    EXPECT_TRUE(near3(irradiance(l, hazy(), l.position), l.intensity / 0.01, 1e-14));
    // r0 = 0 is floored rather than dividing by zero.
    l.r0 = 0.0;
    EXPECT_TRUE(test::finite3(irradiance(l, hazy(), l.position)));
}

TEST(Light, DirectionalIsUnattenuatedAndIgnoresPosition) {
    Light l;
    l.type = Light::Directional;
    l.position = {1e6, 0.0, 0.0};
    l.intensity = {3.0, 2.0, 1.0};
    EXPECT_EQ(irradiance(l, hazy(), {-5e3, 7.0, 1e4}), l.intensity);
}

TEST(Light, SpotSingleConeAndRange) {
    Light l;
    l.type = Light::Spot;
    l.position = {0.0, 10.0, 0.0};
    l.direction = {0.0, -1.0, 0.0};
    l.outerAngle = l.innerAngle = kPi / 6.0;
    l.range = 20.0;
    Medium m;
    const double edge = 10.0 * std::tan(kPi / 6.0);  // cone radius at y = 0
    EXPECT_GT(irradiance(l, m, {0.0, 0.0, 0.0}).x, 0.0);
    EXPECT_GT(irradiance(l, m, {edge * 0.999, 0.0, 0.0}).x, 0.0);
    EXPECT_EQ(irradiance(l, m, {edge * 1.001, 0.0, 0.0}).x, 0.0);
    // The mirrored cone above the apex is dark.
    EXPECT_EQ(irradiance(l, m, {0.0, 15.0, 0.0}).x, 0.0);
    // Inside the cone but beyond range.
    EXPECT_GT(irradiance(l, m, {0.0, -9.9, 0.0}).x, 0.0);
    EXPECT_EQ(irradiance(l, m, {0.0, -10.1, 0.0}).x, 0.0);
    // The apex is lit (finite, I / r0^2).
    EXPECT_DOUBLE_EQ(irradiance(l, m, l.position).x, 1.0 / (0.05 * 0.05));
}

TEST(Light, ScatteringAngleConventions) {
    Light point;
    point.position = {0.0, 0.0, -10.0};
    const glm::dvec3 v{0.0, 0.0, -1.0};
    // Looking straight into the light from in front of it: cos = 1; from beyond it: cos = -1.
    EXPECT_DOUBLE_EQ(cosTheta(point, v, {0.0, 0.0, -2.0}), 1.0);
    EXPECT_DOUBLE_EQ(cosTheta(point, v, {0.0, 0.0, -12.0}), -1.0);
    EXPECT_NEAR(cosTheta(point, v, {3.0, 0.0, -10.0}), 0.0, 1e-16);
    EXPECT_EQ(cosTheta(point, v, point.position), 0.0);
    Light sun;
    sun.type = Light::Directional;
    sun.direction = {0.0, 0.0, 2.0};  // travels towards +z, towards a camera looking down -z
    EXPECT_DOUBLE_EQ(cosTheta(sun, v, {5.0, 5.0, 5.0}), 1.0);
    sun.direction = {1.0, 0.0, 0.0};
    EXPECT_DOUBLE_EQ(cosTheta(sun, v, {}), 0.0);
}

}  // namespace
}  // namespace ls::ref
