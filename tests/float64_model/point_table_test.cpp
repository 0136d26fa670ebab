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

// s is measured from the light's projection along the view direction: a camera 10 m short of it
// has sCamera = -10.
TEST(PointTable, FrameSignConvention) {
    Light l;
    l.position = {3.0, 0.0, -10.0};
    const Ray ray{{0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 50.0};
    const PointRayFrame f = pointRayFrame(l, ray);
    EXPECT_DOUBLE_EQ(f.h, 3.0);
    EXPECT_DOUBLE_EQ(f.sCamera, -10.0);
}

// Without extinction and with an isotropic phase the table has a closed form,
// I betaM/(4 pi) (pi/2 - atan(s/w)) / w, written with atan2 so that large s keeps its digits.
// The integrand then decays only as 1/x^2, which exercises the truncation of the infinite range.
TEST(PointTable, MatchesClosedFormWithoutExtinction) {
    Medium m;
    m.miePhase = Medium::Isotropic;
    m.betaM = {1e-2, 1e-2, 1e-2};
    m.sigmaA = -m.betaM;
    Light l;
    l.intensity = {2.0, 2.0, 2.0};
    l.r0 = 0.05;
    for (double h : {0.0, 0.3, 20.0}) {
        for (double s : {-1e4, -5.0, 0.0, 1.0, 300.0, 1e7}) {
            const double w = std::sqrt(h * h + l.r0 * l.r0);
            const double expected = 2.0 * 1e-2 / (4.0 * kPi) * std::atan2(w, s) / w;
            EXPECT_NEAR(pointTable(m, l, h, s).x / expected, 1.0, 1e-9) << "h=" << h << " s=" << s;
        }
    }
}

Medium hazy(double g) {
    Medium m;
    m.betaR = {2e-3, 5e-3, 1e-2};
    m.betaM = {3e-2, 3e-2, 3e-2};
    m.sigmaA = {1e-2, 0.0, 0.0};
    m.g = g;
    return m;
}

struct Case {
    const char* name;
    glm::dvec3 light;
    double length;
    std::vector<Interval> lit;
};

const std::vector<Case> kCases = {
    {"ahead, all lit", {1.0, 0.5, -20.0}, 60.0, {{0.0, 60.0}}},
    {"ahead, shadowed", {1.0, 0.5, -20.0}, 60.0, {{0.0, 12.0}, {18.0, 25.0}, {40.0, 60.0}}},
    {"through the light", {0.0, 0.0, -15.0}, 40.0, {{0.0, 40.0}}},
    {"behind the camera", {0.0, 2.0, 10.0}, 80.0, {{5.0, 80.0}}},
    {"beyond the end", {0.0, 2.0, -90.0}, 30.0, {{0.0, 30.0}}},
    {"far and long", {10.0, 0.0, -300.0}, 2000.0, {{0.0, 280.0}, {310.0, 2000.0}}},
};

// The table route (docs/model.md's T and its lit-segment combination) against direct quadrature.
TEST(PointTable, LitSegmentsMatchDirectIntegral) {
    for (double g : {0.0, 0.76}) {
        const Medium m = hazy(g);
        for (const Case& c : kCases) {
            Light l;
            l.position = c.light;
            l.intensity = {4.0, 3.0, 2.0};
            const Ray ray{{0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, c.length};
            const QuadResult direct = integrateInscatter(m, l, ray, c.lit);
            ASSERT_TRUE(direct.converged) << c.name;
            EXPECT_TRUE(near3(inscatterFromPointTable(m, l, ray, c.lit), direct.value, 1e-8))
                << c.name << " g=" << g;
        }
    }
}

// pointTableSegment in table coordinates, with the camera somewhere before the segment.
TEST(PointTable, SegmentInTableCoordinates) {
    const Medium m = hazy(0.5);
    Light l;
    l.position = {0.0, 4.0, -30.0};
    const Ray ray{{0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 100.0};
    const PointRayFrame f = pointRayFrame(l, ray);
    const std::vector<Interval> lit{{22.0, 41.0}};
    const glm::dvec3 segment =
        pointTableSegment(m, l, f.h, f.sCamera, f.sCamera + 22.0, f.sCamera + 41.0);
    EXPECT_TRUE(near3(segment, integrateInscatter(m, l, ray, lit).value, 1e-8));
}

// A spot's cone and range cut the ray into the segments the table is summed over; the result must
// match quadrature of the spot's own irradiance, which zeroes outside the cone by itself.
TEST(PointTable, SpotShapedSegmentsMatchDirectIntegral) {
    const Medium m = hazy(0.6);
    Light spot;
    spot.type = Light::Spot;
    spot.position = {0.0, 10.0, -30.0};
    spot.direction = {0.2, -1.0, 0.1};
    spot.outerAngle = spot.innerAngle = 0.45;
    spot.range = 13.0;
    const Ray ray{{-1.0, 0.0, 0.0}, glm::normalize(glm::dvec3(0.05, 0.0, -1.0)), 80.0};
    ASSERT_EQ(spotLitIntervals(spot, ray).size(), 1u);  // the ray does cross the lit volume
    for (const auto& lit :
         std::vector<std::vector<Interval>>{{{0.0, 80.0}}, {{0.0, 29.0}, {31.5, 80.0}}}) {
        const QuadResult direct = integrateInscatter(m, spot, ray, lit);
        ASSERT_TRUE(direct.converged);
        ASSERT_GT(direct.value.x, 0.0);
        EXPECT_TRUE(near3(inscatterFromPointTable(m, spot, ray, lit), direct.value, 1e-8));
    }
}

}  // namespace
}  // namespace ls::ref
