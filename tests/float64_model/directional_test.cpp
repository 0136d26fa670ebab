#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "float64_model/closed_forms.h"
#include "float64_model/inscatter_integral.h"
#include "test_util.h"

namespace ls::ref {
namespace {

using test::near3;

Light sunAt(double angle) {
    Light sun;
    sun.type = Light::Directional;
    sun.direction = {std::sin(angle), -0.3, std::cos(angle)};  // deliberately not unit
    sun.intensity = {1.0, 0.9, 0.7};
    return sun;
}

Ray viewRay(double length) {
    return {{3.0, 1.5, -2.0}, {0.0, 0.0, -1.0}, length};
}

struct MediumCase {
    const char* name;
    glm::dvec3 betaR;
    glm::dvec3 betaM;
    glm::dvec3 sigmaA;
};

const std::vector<MediumCase> kMedia = {
    {"thin", {5.8e-6, 1.35e-5, 3.31e-5}, {2e-6, 2e-6, 2e-6}, {0.0, 0.0, 0.0}},
    {"moderate", {1e-3, 2e-3, 4e-3}, {2e-2, 2e-2, 2e-2}, {1e-3, 0.0, 0.0}},
    {"dense", {0.1, 0.2, 0.3}, {0.5, 0.5, 0.5}, {0.2, 0.0, 0.0}},
    {"zero blue", {1e-3, 2e-3, 0.0}, {2e-2, 2e-2, 0.0}, {0.0, 0.0, 0.0}},
};

// Hoffman-Preetham against the quadrature of docs/model.md's integral, over angles (looking into,
// across and away from the sun), Mie asymmetries, lengths from 1 m to 10 km and the media above.
TEST(Directional, ClosedFormMatchesIntegral) {
    for (const MediumCase& mc : kMedia) {
        for (double g : {-0.5, 0.0, 0.76, 0.95}) {
            for (double angle : {0.0, 0.4, kPi / 2, 2.5, kPi}) {
                for (double length : {1.0, 250.0, 1e4}) {
                    Medium m;
                    m.betaR = mc.betaR;
                    m.betaM = mc.betaM;
                    m.sigmaA = mc.sigmaA;
                    m.g = g;
                    const QuadResult num = integrateInscatter(m, sunAt(angle), viewRay(length));
                    const glm::dvec3 closed =
                        directionalClosedForm(m, sunAt(angle), viewRay(length));
                    ASSERT_TRUE(num.converged);
                    ASSERT_TRUE(near3(closed, num.value, 1e-9))
                        << mc.name << " g=" << g << " angle=" << angle << " S=" << length;
                }
            }
        }
    }
}

// Values that do not depend on the quadrature: the zero channel gives E P S, the thin medium over
// 10 km is within betaT S / 2 of the unattenuated E P S, and a dense medium saturates at E P /
// betaT.
TEST(Directional, LimitsOfTheClosedForm) {
    Medium m;
    m.betaR = {1e-5, 0.0, 0.0};
    m.sigmaA = {0.0, 0.0, 3.0};
    const Light sun = sunAt(0.7);
    const double S = 1e4;
    const double cosT = cosTheta(sun, viewRay(S).direction, {});
    const glm::dvec3 lin = directionalClosedForm(m, sun, viewRay(S));
    const double unattenuated = sun.intensity.x * 1e-5 * Medium::pR(cosT) * S;
    EXPECT_NEAR(lin.x / unattenuated, -std::expm1(-0.1) / 0.1, 1e-14);
    EXPECT_EQ(lin.y, 0.0);  // no scattering at all in green
    EXPECT_EQ(lin.z, 0.0);  // blue only absorbs
    m.betaM = {0.0, 0.0, 1.0};
    const glm::dvec3 dense = directionalClosedForm(m, sun, viewRay(S));
    EXPECT_NEAR(dense.z, sun.intensity.z * phaseCornetteShanks(cosT, 0.0) * 1.0 / 4.0, 1e-15);
    // betaT = 0 in a scattering channel cannot happen physically; with sigmaA = -betaM it does,
    // and the result must be E P S, not 0/0.
    m.sigmaA = {0.0, 0.0, -1.0};
    const glm::dvec3 flat = directionalClosedForm(m, sun, viewRay(S));
    EXPECT_NEAR(flat.z, sun.intensity.z * phaseCornetteShanks(cosT, 0.0) * S, 1e-12);
}

TEST(Directional, ShadowedSegmentsMatchIntegral) {
    const std::vector<std::vector<Interval>> shadows = {
        {{0.0, 5.0}},
        {{10.0, 40.0}, {80.0, 81.0}, {500.0, 9000.0}},
        {{30.0, 70.0}, {50.0, 120.0}, {-5.0, 2.0}, {9500.0, 2e4}},  // overlapping and out of range
        {{3000.0, 3000.0}},                                         // empty
    };
    for (const MediumCase& mc : kMedia) {
        Medium m;
        m.betaR = mc.betaR;
        m.betaM = mc.betaM;
        m.sigmaA = mc.sigmaA;
        m.g = 0.8;
        for (const auto& lit : shadows) {
            const QuadResult num = integrateInscatter(m, sunAt(0.3), viewRay(1e4), lit);
            const glm::dvec3 closed = directionalClosedForm(m, sunAt(0.3), viewRay(1e4), lit);
            ASSERT_TRUE(num.converged);
            ASSERT_TRUE(near3(closed, num.value, 1e-9, 1e-300)) << mc.name;
        }
    }
}

// The segment form must keep its digits in a thin medium far from the camera, where
// exp(-a) - exp(-b) does not: compare with the series of the exact integral in long double.
TEST(Directional, AttenuatedLengthKeepsDigitsInThinMedia) {
    const double beta = 1e-9;
    const double a = 2e4;
    const double b = a + 0.5;
    const long double x = static_cast<long double>(beta) * 0.5L;
    const long double exact =
        std::exp(-static_cast<long double>(beta) * a) * 0.5L * (1.0L - x / 2.0L + x * x / 6.0L);
    const double safe = attenuatedLength(beta, a, b);
    EXPECT_NEAR(safe / static_cast<double>(exact), 1.0, 1e-15);
    const double naive = (std::exp(-beta * a) - std::exp(-beta * b)) / beta;
    EXPECT_GT(std::abs(naive / static_cast<double>(exact) - 1.0), 1e-9);  // why the rule exists
    // A subnormal beta must still give the length (expm1(-x)/beta would round x to 2 ulps).
    EXPECT_EQ(attenuatedLength(5e-324, 0.0, 1.5), 1.5);
    EXPECT_EQ(attenuatedLength(0.0, 2.0, 5.0), 3.0);
    EXPECT_EQ(attenuatedLength(1.0, 5.0, 2.0), 0.0);
}

TEST(Directional, RejectsOtherLights) {
    Light point;
    EXPECT_THROW((void)directionalClosedForm(Medium{}, point, viewRay(1.0)), std::invalid_argument);
}

}  // namespace
}  // namespace ls::ref
