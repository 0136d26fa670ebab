#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "float64_model/closed_forms.h"
#include "float64_model/inscatter_integral.h"
#include "float64_model/point_table.h"
#include "test_util.h"

namespace ls::ref {
namespace {

using test::finite3;
using test::near3;
using test::nonNegative3;

Medium withZeroChannel() {
    Medium m;
    m.betaR = {2e-3, 5e-3, 0.0};
    m.betaM = {3e-2, 3e-2, 0.0};
    m.g = 0.9;
    return m;
}

Light pointLight(const glm::dvec3& at, double r0 = 0.05) {
    Light l;
    l.position = at;
    l.r0 = r0;
    return l;
}

// Every route for a point light, checked finite and non-negative; returns the quadrature value.
glm::dvec3 allRoutesFinite(const Medium& m, const Light& l, const Ray& ray) {
    const QuadResult num = integrateInscatter(m, l, ray);
    const glm::dvec3 table = inscatterFromPointTable(m, l, ray);
    EXPECT_TRUE(finite3(num.value) && nonNegative3(num.value));
    EXPECT_TRUE(finite3(table) && nonNegative3(table));
    EXPECT_TRUE(num.converged);
    EXPECT_TRUE(near3(table, num.value, 1e-8));
    return num.value;
}

TEST(HardCases, LightAtTheCamera) {
    const Ray ray{{1.0, 2.0, 3.0}, {0.0, 0.0, -1.0}, 50.0};
    const glm::dvec3 v = allRoutesFinite(withZeroChannel(), pointLight(ray.origin), ray);
    EXPECT_GT(v.x, 0.0);
    EXPECT_EQ(v.z, 0.0);
    // Value check with the closed form: b = 0, w = r0, so atan(S/r0)/r0.
    Medium flat;
    flat.miePhase = Medium::Isotropic;
    flat.betaM = glm::dvec3(1e-2);
    flat.sigmaA = -flat.betaM;
    const double expected = 1e-2 / (4.0 * kPi) * std::atan(50.0 / 0.05) / 0.05;
    EXPECT_NEAR(integrateInscatter(flat, pointLight(ray.origin), ray).value.x / expected, 1.0,
                1e-9);
}

TEST(HardCases, RayThroughTheLightWithZeroRadius) {
    const Ray ray{{0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 40.0};
    const glm::dvec3 v =
        allRoutesFinite(withZeroChannel(), pointLight({0.0, 0.0, -10.0}, 0.0), ray);
    EXPECT_GT(v.x, 0.0);
    // Spot with the camera at its apex, looking down the axis.
    Light s = pointLight(ray.origin, 0.0);
    s.type = Light::Spot;
    s.direction = ray.direction;
    EXPECT_TRUE(finite3(integrateInscatter(withZeroChannel(), s, ray).value));
    EXPECT_TRUE(finite3(inscatterFromPointTable(withZeroChannel(), s, ray)));
}

TEST(HardCases, ZeroExtinctionEverywhere) {
    Medium m;  // betaR = betaM = sigmaA = 0: nothing scatters, nothing attenuates
    const Ray ray{{0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 1e4};
    EXPECT_EQ(allRoutesFinite(m, pointLight({1.0, 0.0, -5.0}), ray), glm::dvec3(0.0));
    Light sun;
    sun.type = Light::Directional;
    EXPECT_EQ(directionalClosedForm(m, sun, ray), glm::dvec3(0.0));
}

TEST(HardCases, ZeroLengthRay) {
    const Ray ray{{0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 0.0};
    const Light l = pointLight({0.0, 0.0, 0.0});
    EXPECT_EQ(integrateInscatter(withZeroChannel(), l, ray).value, glm::dvec3(0.0));
    EXPECT_EQ(inscatterFromPointTable(withZeroChannel(), l, ray), glm::dvec3(0.0));
    Light sun;
    sun.type = Light::Directional;
    EXPECT_EQ(directionalClosedForm(withZeroChannel(), sun, ray), glm::dvec3(0.0));
}

TEST(HardCases, HugeLength) {
    for (double length : {1e7, 1e12}) {
        const Ray ray{{0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, length};
        const glm::dvec3 v = allRoutesFinite(withZeroChannel(), pointLight({3.0, 0.0, -40.0}), ray);
        EXPECT_GT(v.x, 0.0);
        Light sun;
        sun.type = Light::Directional;
        Medium thin;
        thin.betaR = {1e-5, 0.0, 0.0};
        const glm::dvec3 d = directionalClosedForm(thin, sun, ray);
        EXPECT_TRUE(finite3(d));
        // Saturated: E P / betaT.
        EXPECT_NEAR(d.x, Medium::pR(cosTheta(sun, ray.direction, {})), 1e-15);
        const QuadResult num = integrateInscatter(thin, sun, ray);
        EXPECT_TRUE(num.converged);
        EXPECT_TRUE(near3(num.value, d, 1e-9));
    }
}

// Degenerate inputs give 0, never NaN.
TEST(HardCases, DegenerateRaysGiveZero) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const Light l = pointLight({0.0, 0.0, -5.0});
    for (const Ray& ray : {Ray{{}, {0.0, 0.0, 0.0}, 10.0}, Ray{{}, {nan, 0.0, 0.0}, 10.0},
                           Ray{{}, {0.0, 0.0, -1.0}, nan}, Ray{{}, {0.0, 0.0, -1.0}, inf},
                           Ray{{}, {0.0, 0.0, -1.0}, -3.0}}) {
        EXPECT_EQ(integrateInscatter(withZeroChannel(), l, ray).value, glm::dvec3(0.0));
        EXPECT_EQ(inscatterFromPointTable(withZeroChannel(), l, ray), glm::dvec3(0.0));
    }
    const std::vector<Interval> junk{{nan, 3.0}, {2.0, nan}, {5.0, 1.0}};
    const Ray ray{{}, {0.0, 0.0, -1.0}, 10.0};
    EXPECT_EQ(integrateInscatter(withZeroChannel(), l, ray, junk).value, glm::dvec3(0.0));
}

}  // namespace
}  // namespace ls::ref
