#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "float64_model/gauss_kronrod.h"
#include "float64_model/medium.h"
#include "float64_model/ray_geometry.h"
#include "test_util.h"

namespace ls::ref {
namespace {

// Integral over the sphere, 2 pi * integral over mu in [-1, 1]; the mesh towards both poles
// resolves a strongly peaked lobe (g = 0.99 peaks within about 1e-4 of mu = 1).
double sphereIntegral(double (*phase)(double, double), double g) {
    std::vector<double> cuts;
    appendGeometricMesh(cuts, 1.0, 1e-7, -1.0, -1.0, 1.0);
    appendGeometricMesh(cuts, -1.0, 1e-7, 1.0, -1.0, 1.0);
    const Interval whole{-1.0, 1.0};
    const QuadResult r =
        integrateAdaptive([&](double mu) { return glm::dvec3(2.0 * kPi * phase(mu, g)); },
                          splitAt({&whole, 1}, cuts));
    EXPECT_TRUE(r.converged);
    return r.value.x;
}

TEST(Phase, RayleighNormalised) {
    EXPECT_NEAR(sphereIntegral([](double mu, double) { return Medium::pR(mu); }, 0.0), 1.0, 1e-12);
}

TEST(Phase, CornetteShanksNormalisedForEveryG) {
    for (double g : {-0.95, -0.5, 0.0, 0.3, 0.76, 0.9, 0.99}) {
        EXPECT_NEAR(sphereIntegral(phaseCornetteShanks, g), 1.0, 1e-10) << "g = " << g;
    }
}

TEST(Phase, IsotropicLobeNormalisedAndReplacesOnlyMie) {
    Medium m;
    m.miePhase = Medium::Isotropic;
    m.g = 0.8;  // must be ignored
    m.betaR = {1.0, 0.0, 2.0};
    m.betaM = {0.0, 3.0, 5.0};
    for (double mu : {-1.0, -0.2, 0.5, 1.0}) {
        EXPECT_DOUBLE_EQ(m.pM(mu), 1.0 / (4.0 * kPi));
        const glm::dvec3 expected =
            m.betaR * (3.0 / (16.0 * kPi) * (1.0 + mu * mu)) + m.betaM / (4.0 * kPi);
        EXPECT_TRUE(test::near3(m.P(mu), expected, 1e-15));
    }
}

// Cornette-Shanks at g = 0 is the Rayleigh shape (3/4 (1 + mu^2) / (4 pi)).
TEST(Phase, CornetteShanksAtZeroGIsRayleigh) {
    for (double mu : {-1.0, -0.3, 0.0, 0.7, 1.0}) {
        EXPECT_NEAR(phaseCornetteShanks(mu, 0.0), Medium::pR(mu), 1e-16);
    }
}

// Looking into the light (cos = 1) is where forward scattering (g > 0) peaks.
TEST(Phase, ForwardLobePeaksTowardsTheLight) {
    EXPECT_GT(phaseCornetteShanks(1.0, 0.8), 100.0 * phaseCornetteShanks(-1.0, 0.8));
    EXPECT_GT(phaseCornetteShanks(-1.0, -0.8), 100.0 * phaseCornetteShanks(1.0, -0.8));
    // Value at the peak, from 1/(4 pi) 3(1-g^2)/(2(2+g^2)) 2/(1-g)^3.
    const double g = 0.8;
    EXPECT_NEAR(phaseCornetteShanks(1.0, g),
                3.0 * (1 - g * g) / (2.0 * (2 + g * g)) * 2.0 / std::pow(1 - g, 3) / (4 * kPi),
                1e-12);
}

TEST(Phase, MaxPBoundsEveryAngle) {
    for (double g : {-0.9, 0.0, 0.5, 0.95}) {
        Medium m;
        m.g = g;
        m.betaR = {1e-3, 2e-3, 0.0};
        m.betaM = {5e-3, 0.0, 1e-3};
        const glm::dvec3 bound = m.maxP();
        for (int i = 0; i <= 2000; ++i) {
            const glm::dvec3 p = m.P(-1.0 + i * 1e-3);
            for (int c = 0; c < 3; ++c) ASSERT_LE(p[c], bound[c] * (1 + 1e-15)) << g << " " << i;
        }
    }
}

}  // namespace
// Seed 004's hazy phase function (its equation 2.4) with K = 1/(8 pi): normalised over the sphere,
// and the seed's own K (appendix A, 1/16.45948) reproduced from the integral it wrote down, which
// weights each ring by sqrt(1 - x^2) and so normalises the function to about 1.527, not 1.
TEST(Phase, HazyNormalisedAndTheSeedsKExplained) {
    EXPECT_NEAR(sphereIntegral([](double mu, double) { return phaseHazy(mu); }, 0.0), 1.0, 1e-12);
    EXPECT_NEAR(phaseHazy(1.0), 10.0 * kHazyK, 1e-15);                 // 1 + 9 cos^16(0)
    EXPECT_NEAR(phaseHazy(-1.0), kHazyK, 1e-15);                       // cos(pi / 2) = 0
    EXPECT_NEAR(phaseHazy(0.0), kHazyK * (1.0 + 9.0 / 256.0), 1e-15);  // cos^16(pi / 4) = 2^-8
    const Interval whole{-1.0, 1.0};
    auto unnormalised = [](double x) { return 1.0 + 9.0 * std::pow(0.5 * (1.0 + x), 8.0); };
    const QuadResult seeds = integrateAdaptive(
        [&](double x) { return glm::dvec3(2.0 * kPi * unnormalised(x) * std::sqrt(1.0 - x * x)); },
        {&whole, 1});
    EXPECT_NEAR(seeds.value.x, 54647.0 * kPi * kPi / 32768.0, 1e-9);  // appendix A's value
    EXPECT_NEAR(1.0 / kSeed004HazyK, 16.45948, 1e-5);
    const double withSeedsK = sphereIntegral(
        [](double mu, double) {
            return kSeed004HazyK * (1.0 + 9.0 * std::pow(0.5 * (1.0 + mu), 8.0));
        },
        0.0);
    EXPECT_NEAR(withSeedsK, 8.0 * kPi * kSeed004HazyK, 1e-12);
    EXPECT_GT(withSeedsK, 1.5);
    Medium m;
    m.miePhase = Medium::Hazy;
    m.betaM = glm::dvec3(1.0);
    EXPECT_DOUBLE_EQ(m.pM(0.3), phaseHazy(0.3));
    EXPECT_DOUBLE_EQ(m.maxP().x, phaseHazy(1.0));
}

}  // namespace ls::ref
