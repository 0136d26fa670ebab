#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "float64_model/closed_forms.h"
#include "float64_model/inscatter_integral.h"
#include "float64_model/point_table.h"
#include "float64_model/ray_geometry.h"
#include "test_util.h"

namespace ls::ref {
namespace {

using test::near3;

// A spot 10 m above the origin pointing down with a 30 degree half-angle: at y = 0 its cone is a
// disc of radius 10 tan(30 deg), which fixes every lit interval below by hand.
const double kEdge = 10.0 * std::tan(kPi / 6.0);

Light spot(double range = std::numeric_limits<double>::infinity()) {
    Light l;
    l.type = Light::Spot;
    l.position = {0.0, 10.0, 0.0};
    l.direction = {0.0, -1.0, 0.0};
    l.outerAngle = l.innerAngle = kPi / 6.0;
    l.range = range;
    l.intensity = {7.0, 5.0, 3.0};
    return l;
}

Light pointAt(const Light& s) {
    Light p = s;
    p.type = Light::Point;
    return p;
}

Medium hazy() {
    Medium m;
    m.betaR = {2e-3, 5e-3, 1e-2};
    m.betaM = {3e-2, 3e-2, 3e-2};
    m.g = 0.7;
    return m;
}

// The spot equals the point light it is made from, restricted to the hand-derived lit interval.
// edgeTol is in metres along the ray.
void expectSpotIsClippedPoint(const Light& s, const Ray& ray, Interval expected,
                              double edgeTol = 1e-12) {
    const std::vector<Interval> lit = spotLitIntervals(s, ray);
    ASSERT_EQ(lit.size(), 1u);
    EXPECT_NEAR(lit[0].begin, expected.begin, edgeTol);
    EXPECT_NEAR(lit[0].end, expected.end, edgeTol);
    const QuadResult spotLin = integrateInscatter(hazy(), s, ray);
    const QuadResult pointLin = integrateInscatter(hazy(), pointAt(s), ray, {&expected, 1});
    ASSERT_TRUE(spotLin.converged);
    ASSERT_GT(pointLin.value.x, 0.0);
    EXPECT_TRUE(near3(spotLin.value, pointLin.value, 1e-9));
}

TEST(Spot, RayFullyOutsideGivesExactlyZero) {
    const Ray ray{{-50.0, 0.0, 8.0}, {1.0, 0.0, 0.0}, 100.0};  // passes 8 m > kEdge from the axis
    EXPECT_TRUE(spotLitIntervals(spot(), ray).empty());
    EXPECT_EQ(integrateInscatter(hazy(), spot(), ray).value, glm::dvec3(0.0));
    EXPECT_EQ(inscatterFromPointTable(hazy(), spot(), ray), glm::dvec3(0.0));
    // The point light it is made from does light this ray: the zero is the cone's doing.
    EXPECT_GT(integrateInscatter(hazy(), pointAt(spot()), ray).value.x, 0.0);
}

TEST(Spot, MirroredConeIsDark) {
    const Ray ray{{-50.0, 20.0, 0.0}, {1.0, 0.0, 0.0}, 100.0};  // crosses the cone above the apex
    EXPECT_TRUE(spotLitIntervals(spot(), ray).empty());
    EXPECT_EQ(integrateInscatter(hazy(), spot(), ray).value, glm::dvec3(0.0));
}

// Along the axis, down from 2 m below the apex: lit until the 20 m range, 18 m along the ray.
TEST(Spot, RayAlongTheAxis) {
    const Ray ray{{0.0, 8.0, 0.0}, {0.0, -1.0, 0.0}, 30.0};
    expectSpotIsClippedPoint(spot(20.0), ray, {0.0, 18.0});
    // Independent of quadrature: with betaT = 0 and an isotropic phase the cone-clipped closed form
    // is (atan(20/r0) - atan(2/r0))/r0 times I betaM/(4 pi).
    Medium flat;
    flat.miePhase = Medium::Isotropic;
    flat.betaM = glm::dvec3(1e-2);
    flat.sigmaA = -flat.betaM;
    const double r0 = spot().r0;
    const double expected =
        7.0 * 1e-2 / (4.0 * kPi) * (std::atan(20.0 / r0) - std::atan(2.0 / r0)) / r0;
    EXPECT_NEAR(pointArctanClosedForm(flat, spot(20.0), ray).x / expected, 1.0, 1e-13);
    EXPECT_NEAR(integrateInscatter(flat, spot(20.0), ray).value.x / expected, 1.0, 1e-9);
}

TEST(Spot, CameraInsideTheCone) {
    expectSpotIsClippedPoint(spot(), {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 20.0}, {0.0, kEdge});
}

TEST(Spot, CameraOutsideRayCrossesTheCone) {
    expectSpotIsClippedPoint(spot(), {{-20.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 40.0},
                             {20.0 - kEdge, 20.0 + kEdge});
}

// A range of 11 m cuts the disc at y = 0 down to radius sqrt(11^2 - 10^2), inside the cone's.
TEST(Spot, RangeSphereCutsBeforeTheCone) {
    const double r = std::sqrt(21.0);
    expectSpotIsClippedPoint(spot(11.0), {{-20.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 40.0},
                             {20.0 - r, 20.0 + r});
}

TEST(Spot, CameraExactlyOnTheConeSurface) {
    // Looking into the cone: lit across the whole disc.
    expectSpotIsClippedPoint(spot(), {{kEdge, 0.0, 0.0}, {-1.0, 0.0, 0.0}, 30.0},
                             {0.0, 2.0 * kEdge});
    // Looking out of it: nothing but the starting point is lit.
    const Ray out{{kEdge, 0.0, 0.0}, {1.0, 0.0, 0.0}, 30.0};
    EXPECT_LT(integrateInscatter(hazy(), spot(), out).value.x, 1e-12);
    EXPECT_EQ(inscatterFromPointTable(hazy(), spot(), out), glm::dvec3(0.0));
}

// A cone wider than a hemisphere (120 degrees half-angle) is still a single cone: points within
// 60 degrees of the backward axis stay dark.
TEST(Spot, WideConeKeepsItsBackDark) {
    Light wide = spot();
    wide.outerAngle = wide.innerAngle = 2.0 * kPi / 3.0;
    const Ray ray{{-50.0, 20.0, 0.0}, {1.0, 0.0, 0.0}, 100.0};  // 10 m above the apex
    const double dark = 10.0 * std::tan(kPi / 3.0);             // radius of the dark disc there
    const std::vector<Interval> lit = spotLitIntervals(wide, ray);
    ASSERT_EQ(lit.size(), 2u);
    EXPECT_NEAR(lit[0].end, 50.0 - dark, 1e-12);
    EXPECT_NEAR(lit[1].begin, 50.0 + dark, 1e-12);
    const std::vector<Interval> expected{{0.0, 50.0 - dark}, {50.0 + dark, 100.0}};
    EXPECT_TRUE(near3(integrateInscatter(hazy(), wide, ray).value,
                      integrateInscatter(hazy(), pointAt(wide), ray, expected).value, 1e-9));
}

// A 2 mrad-wide beam crossed 300 m from the light's projection: the lit stretch (about 2 m of a
// 10 km ray) lies between the nodes of any rule on the pieces around it, so only the analytic cone
// crossings as breakpoints find it. Its ends are found here by bisection on the inside test alone.
TEST(Spot, NarrowBeamCrossedFarFromTheLight) {
    Light beam = spot();
    beam.position = {0.0, 1000.0, 0.0};
    beam.direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.0));
    beam.outerAngle = beam.innerAngle = 1e-3;
    const Ray ray{{-5000.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 1e4};
    auto inside = [&](double s) { return insideSpot(beam, ray.origin + s * ray.direction); };
    auto edge = [&](double in, double out) {
        for (int i = 0; i < 200; ++i) {
            const double mid = 0.5 * (in + out);
            (inside(mid) ? in : out) = mid;
        }
        return in;
    };
    ASSERT_TRUE(inside(5300.0));
    const Interval expected{edge(5300.0, 5290.0), edge(5300.0, 5310.0)};
    ASSERT_GT(expected.end - expected.begin, 1.0);
    // Where the edge lies is ill-conditioned for a narrow cone: rounding of about 1e-16 |L - P| in
    // the inside test moves it by that over sin(alpha), ~1e-10 m here, for the bisection too.
    expectSpotIsClippedPoint(beam, ray, expected, 1e-8);
}

// KHR_lights_punctual's falloffs (docs/model.md, "The lights"), at points of known angle and
// distance.
TEST(SoftLights, TheFalloffsAreKhrsFormulas) {
    Light s = spot();
    s.innerAngle = kPi / 9.0;  // 20 degrees
    const double cosInner = std::cos(kPi / 9.0), cosOuter = std::cos(kPi / 6.0);
    auto at = [&](double angle, double distance) {
        return s.position + distance * glm::dvec3(std::sin(angle), -std::cos(angle), 0.0);
    };
    EXPECT_EQ(falloff(s, at(0.0, 5.0)), 1.0);
    EXPECT_EQ(falloff(s, at(kPi / 10.0, 5.0)), 1.0);  // inside the inner cone
    const double mid = 0.5 * (kPi / 9.0 + kPi / 6.0);
    const double a = (std::cos(mid) - cosOuter) / (cosInner - cosOuter);
    EXPECT_NEAR(falloff(s, at(mid, 5.0)), a * a, 1e-13);
    EXPECT_EQ(glm::length(irradiance(s, hazy(), at(kPi / 5.0, 5.0))), 0.0);  // beyond the outer
    // A hard edge is a step: full intensity up to the cone.
    EXPECT_EQ(falloff(spot(), at(kPi / 6.0 - 1e-9, 5.0)), 1.0);

    Light p = pointAt(spot(8.0));
    p.windowedRange = true;
    EXPECT_NEAR(falloff(p, at(0.3, 4.0)), 1.0 - 1.0 / 16.0, 1e-15);
    EXPECT_EQ(falloff(p, at(0.3, 8.0)), 0.0);
    EXPECT_EQ(glm::length(irradiance(p, hazy(), at(0.3, 8.5))), 0.0);
    p.windowedRange = false;  // cut: 1 to the range, nothing beyond
    EXPECT_EQ(falloff(p, at(0.3, 7.9)), 1.0);
    EXPECT_EQ(glm::length(irradiance(p, hazy(), at(0.3, 8.1))), 0.0);
}

// The adaptive quadrature with the falloffs under it (breakpoints at both cones and the range)
// against a plain midpoint sum of the integrand with a million steps.
TEST(SoftLights, TheIntegralAgreesWithDirectQuadrature) {
    auto midpoint = [](const Medium& m, const Light& l, const Ray& r) {
        constexpr int kSteps = 1000000;
        const double ds = r.length / kSteps;
        glm::dvec3 sum(0.0);
        for (int k = 0; k < kSteps; ++k) sum += inscatterIntegrand(m, l, r, (k + 0.5) * ds);
        return sum * ds;
    };
    Light soft = spot(14.0);
    soft.innerAngle = kPi / 9.0;
    Light windowed = pointAt(spot(9.0));
    windowed.windowedRange = true;
    // Across the penumbra below the spot, and past the point light inside its range.
    const Ray across{{-12.0, 2.0, 1.0}, glm::normalize(glm::dvec3(1.0, 0.05, 0.0)), 24.0};
    for (const Light& l : {soft, windowed}) {
        const QuadResult q = integrateInscatter(hazy(), l, across);
        ASSERT_TRUE(q.converged);
        const glm::dvec3 want = midpoint(hazy(), l, across);
        ASSERT_GT(want.x, 0.0);
        EXPECT_TRUE(near3(q.value, want, 1e-6)) << q.value.x << " vs " << want.x;
    }
}

}  // namespace
}  // namespace ls::ref
