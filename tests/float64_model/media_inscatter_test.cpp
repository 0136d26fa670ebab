// Lin in a non-uniform medium (docs/model.md, "Non-uniform media"): the directional closed form
// and the adaptive quadrature for point and spot lights against a brute-force midpoint rule that
// integrates every optical depth numerically (media_brute_force.h); and the homogeneous medium
// still taking its own path.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include "float64_model/closed_forms.h"
#include "float64_model/inscatter_integral.h"
#include "float64_model/optical_depth.h"
#include "float64_model/point_table.h"
#include "float64_model/ray_geometry.h"
#include "float64_model/transmittance.h"
#include "media_brute_force.h"
#include "test_util.h"

namespace ls::ref {
namespace {

using test::bruteInscatter;
using test::near3;

// The brute force's panels: its own error is O(h^2) (every jump is at a panel's end), at most
// 1.3e-7 of Lin here (LS_BRUTE_CONVERGENCE=1 prints it against 4x finer panels, which moves it by
// that much and the model by 1/16 of it), so 1e-6 is the bound the model is held to.
constexpr int kRayPanels = 10000;
constexpr int kLightPanels = 300;
constexpr double kBruteTol = 1e-6;

Medium coefficients() {
    Medium m;
    m.betaR = {2e-3, 5e-3, 1e-2};
    m.betaM = glm::dvec3(0.04);
    m.sigmaA = {0.01, 0.0, 0.005};
    m.g = 0.6;
    return m;
}

FogBox tiltedBox(double fade) {
    FogBox b;
    b.center = {0.5, 1.5, -2.0};
    b.halfExtents = {2.0, 1.0, 3.0};
    const glm::dvec3 x = glm::normalize(glm::dvec3(1.0, 0.2, 0.3));
    const glm::dvec3 y = glm::normalize(glm::cross(glm::dvec3(0.0, 0.0, 1.0), x));
    b.axes = {x, y, glm::cross(x, y)};
    b.density = 3.0;
    b.fade = fade;
    return b;
}

struct NamedMedium {
    std::string name;
    Medium medium;
};

std::vector<NamedMedium> media() {
    std::vector<NamedMedium> out;
    Medium fog = coefficients();
    fog.density.heightFog = HeightFog{1.0, 0.8};
    out.push_back({"height fog", fog});

    Medium box = coefficients();
    box.density.base = 0.2;  // thin air around a dense faded box
    box.density.volumes.push_back(tiltedBox(0.6));
    out.push_back({"faded box in thin air", box});

    Medium mixed = coefficients();
    mixed.density.base = 0.7;
    mixed.density.heightFog = HeightFog{0.5, 1.5};
    mixed.density.volumes.push_back(tiltedBox(0.0));
    FogBox wide = tiltedBox(4.0);  // a fade wider than the box
    wide.center = {-1.0, 2.5, -6.0};
    wide.density = 5.0;
    mixed.density.volumes.push_back(wide);
    out.push_back({"height fog, a hard box and a wide fade", mixed});
    return out;
}

Light sun() {
    Light l;
    l.type = Light::Directional;
    l.direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
    l.intensity = {10.0, 9.0, 8.0};
    return l;
}

Light point() {
    Light l;
    l.type = Light::Point;
    l.position = {1.0, 3.0, -4.0};
    l.intensity = {40.0, 30.0, 20.0};
    return l;
}

Light spot() {
    Light l = point();
    l.type = Light::Spot;
    l.position = {0.0, 5.0, -3.0};
    l.direction = glm::normalize(glm::dvec3(0.1, -1.0, -0.2));
    l.outerAngle = 0.5;
    l.innerAngle = 0.35;
    return l;
}

// From above the fog's base height down and through it, the boxes and past both lights.
Ray viewRay() {
    return {{0.0, 2.2, 8.0}, glm::normalize(glm::dvec3(0.3, -1.6, -18.0)), 24.0};
}

// The largest relative difference over the channels.
double maxRelative(const glm::dvec3& a, const glm::dvec3& b) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a[c] - b[c]) / std::abs(b[c]));
    return worst;
}

void expectBruteForceAgrees(const Light& light) {
    const Ray ray = viewRay();
    for (const NamedMedium& nm : media()) {
        SCOPED_TRACE(nm.name);
        const glm::dvec3 brute = bruteInscatter(nm.medium, light, ray, kRayPanels, kLightPanels);
        const QuadResult quad = integrateInscatter(nm.medium, light, ray);
        ASSERT_TRUE(quad.converged);
        EXPECT_TRUE(near3(quad.value, brute, kBruteTol));
        // The same coefficients in a uniform medium (m = 1) miss by far more: the bound can fail.
        Medium uniform = nm.medium;
        uniform.density = Density{};
        const glm::dvec3 wrong = integrateInscatter(uniform, light, ray).value;
        EXPECT_FALSE(near3(wrong, brute, 100.0 * kBruteTol));
        std::printf(
            "%s: model vs brute force %.1e, uniform medium vs brute force %.1e (%d evaluations)\n",
            nm.name.c_str(), maxRelative(quad.value, brute), maxRelative(wrong, brute),
            quad.evaluations);
        if (std::getenv("LS_BRUTE_CONVERGENCE")) {
            const glm::dvec3 finer =
                bruteInscatter(nm.medium, light, ray, 4 * kRayPanels, 4 * kLightPanels);
            std::printf("  brute force vs 4x finer %.1e, model vs 4x finer %.1e\n",
                        maxRelative(brute, finer), maxRelative(quad.value, finer));
        }
    }
}

TEST(MediaInscatter, DirectionalAgreesWithTheBruteForce) {
    expectBruteForceAgrees(sun());
}

TEST(MediaInscatter, PointAgreesWithTheBruteForce) {
    expectBruteForceAgrees(point());
}

TEST(MediaInscatter, SpotAgreesWithTheBruteForce) {
    expectBruteForceAgrees(spot());
}

// The sun's closed form E P T(a) (-expm1(-betaT dtau)) / betaT per lit run is exact: it matches
// the adaptive quadrature of the same integrand to its tolerance, with shadows cutting the ray.
TEST(MediaInscatter, DirectionalClosedFormIsExactOnLitRuns) {
    const Ray ray = viewRay();
    const std::vector<Interval> lit{{0.5, 3.0}, {7.0, 9.5}, {12.0, 30.0}};
    for (const NamedMedium& nm : media()) {
        SCOPED_TRACE(nm.name);
        const QuadResult quad = integrateInscatter(nm.medium, sun(), ray, lit);
        ASSERT_TRUE(quad.converged);
        EXPECT_TRUE(near3(directionalClosedForm(nm.medium, sun(), ray, lit), quad.value, 1e-9));
    }
}

// A channel with betaT = 0: T = 1 and the lit run gives E P dtau, the limit of the closed form.
TEST(MediaInscatter, DirectionalZeroExtinctionChannelIsTheOpticalDepth) {
    Medium m = media()[2].medium;
    m.betaR.z = 0.0;
    m.betaM.z = 0.0;
    m.sigmaA.z = 0.0;
    const Ray ray = viewRay();
    const glm::dvec3 lin = directionalClosedForm(m, sun(), ray);
    const double tau = opticalDepth(m.density, ray, 0.0, ray.length);
    EXPECT_EQ(lin.z, 0.0);  // no scattering either in that channel
    m.betaM.z = 0.03;
    m.sigmaA.z = -0.03;  // scattering without extinction
    const double p = m.P(cosTheta(sun(), ray.direction, ray.origin)).z;
    EXPECT_NEAR(directionalClosedForm(m, sun(), ray).z, sun().intensity.z * p * tau,
                1e-14 * sun().intensity.z * p * tau);
    EXPECT_EQ(viewTransmittance(m, ray).z, 1.0);
}

TEST(MediaInscatter, PointLightIsDimmedByTheOpticalDepthToIt) {
    Medium m = media()[1].medium;
    const Light l = point();
    const glm::dvec3 x{0.0, 1.0, 0.0};
    const double r = glm::length(l.position - x);
    const double r0 = effectiveRadius(l);
    const glm::dvec3 expected = l.intensity *
                                glm::exp(-m.betaT() * opticalDepth(m.density, x, l.position)) /
                                (r * r + r0 * r0);
    EXPECT_TRUE(near3(irradiance(l, m, x), expected, 1e-15));
    // A directional light is not dimmed on its way in.
    EXPECT_EQ(irradiance(sun(), m, x), sun().intensity);
}

TEST(MediaInscatter, ViewTransmittanceIsTheRaysOpticalDepth) {
    const Medium m = media()[2].medium;
    Ray ray = viewRay();
    const double tau = opticalDepth(m.density, ray, 0.0, ray.length);
    EXPECT_TRUE(near3(viewTransmittance(m, ray), glm::exp(-m.betaT() * tau), 1e-15));
    const double brute =
        test::bruteOpticalDepth(m.density, ray.origin, ray.direction, 0.0, ray.length, 200000);
    EXPECT_NEAR(tau, brute, 1e-8 * brute);
    ray.direction *= 3.0;  // any length of direction
    EXPECT_TRUE(near3(viewTransmittance(m, ray), glm::exp(-m.betaT() * tau), 1e-14));
    ray.direction = glm::dvec3(0.0);
    EXPECT_EQ(viewTransmittance(m, ray), glm::dvec3(1.0));
}

// The homogeneous medium (no fog, no volumes) keeps its own path; with a density d0 that is not
// folded into the coefficients, the general path gives what folding it gives.
TEST(MediaInscatter, HomogeneousDensityEqualsFoldedCoefficients) {
    Medium loose = coefficients();
    loose.density.base = 2.5;
    Medium folded = coefficients();
    folded.betaR *= 2.5;
    folded.betaM *= 2.5;
    folded.sigmaA *= 2.5;
    const Ray ray = viewRay();
    for (const Light& l : {sun(), point(), spot()}) {
        EXPECT_TRUE(near3(integrateInscatter(loose, l, ray).value,
                          integrateInscatter(folded, l, ray).value, 1e-9));
    }
    EXPECT_TRUE(near3(directionalClosedForm(loose, sun(), ray),
                      directionalClosedForm(folded, sun(), ray), 1e-13));
    EXPECT_TRUE(near3(viewTransmittance(loose, ray), viewTransmittance(folded, ray), 1e-14));
}

// Height fog of falloff 0 and a volume of density 0 leave m = 1: the general path then gives the
// homogeneous numbers.
TEST(MediaInscatter, NonUniformFormOfAUnitDensityGivesTheHomogeneousNumbers) {
    Medium general = coefficients();
    general.density.heightFog = HeightFog{3.0, 0.0};
    FogBox empty = tiltedBox(0.5);
    empty.density = 0.0;
    general.density.volumes.push_back(empty);
    ASSERT_FALSE(general.density.unit());
    const Medium plain = coefficients();
    const Ray ray = viewRay();
    for (const Light& l : {sun(), point(), spot()}) {
        EXPECT_TRUE(near3(integrateInscatter(general, l, ray).value,
                          integrateInscatter(plain, l, ray).value, 1e-9));
    }
    const std::vector<Interval> lit{{1.0, 4.0}, {6.0, 20.0}};
    EXPECT_TRUE(near3(directionalClosedForm(general, sun(), ray, lit),
                      directionalClosedForm(plain, sun(), ray, lit), 1e-13));
}

// With m = 1 the integrand, the pieces and the closed form are the homogeneous model's own, as
// written before the medium could vary: so every homogeneous reference stays the same bit for bit.
TEST(MediaInscatter, UnitDensityTakesTheHomogeneousPathBitForBit) {
    const Medium m = coefficients();
    const Ray ray = *unitRay(viewRay());  // as integrateInscatter normalises it
    const glm::dvec3 beta = m.betaT();
    for (const Light& l : {point(), spot()}) {
        const glm::dvec3 x = ray.origin + 7.0 * ray.direction;
        const double r = glm::length(l.position - x), r0 = effectiveRadius(l);
        EXPECT_EQ(irradiance(l, m, x),
                  l.intensity * glm::exp(-beta * r) / (r * r + r0 * r0) * falloff(l, x));
        EXPECT_EQ(inscatterIntegrand(m, l, ray, 7.0),
                  glm::exp(-beta * 7.0) * m.P(cosTheta(l, ray.direction, x)) * irradiance(l, m, x));
        std::vector<double> cuts = lightFeatureDistances(l, ray);
        appendGeometricMesh(cuts, 0.0, 1.0 / (16.0 * std::max({beta.x, beta.y, beta.z})), 1.0, 0.0,
                            ray.length);
        const Interval whole{0.0, ray.length};
        const std::vector<Interval> pieces = splitAt({&whole, 1}, cuts);
        const QuadResult before = integrateAdaptive(
            [&](double s) {
                const glm::dvec3 p = ray.origin + s * ray.direction;
                return glm::exp(-beta * s) * m.P(cosTheta(l, ray.direction, p)) *
                       irradiance(l, m, p);
            },
            pieces);
        EXPECT_EQ(integrateInscatter(m, l, ray).value, before.value);
    }
    const glm::dvec3 sunLin = sun().intensity * m.P(cosTheta(sun(), ray.direction, ray.origin)) *
                              attenuatedLength(beta, 0.0, ray.length);
    EXPECT_EQ(directionalClosedForm(m, sun(), ray), sunLin);
    EXPECT_EQ(viewTransmittance(m, ray), glm::exp(-beta * ray.length));
}

// The homogeneous medium's closed forms and table assume m = 1 everywhere: they refuse a medium
// that varies rather than answer for another one.
TEST(MediaInscatter, HomogeneousOnlyFormsRefuseAVaryingMedium) {
    const Medium m = media()[0].medium;
    const Ray ray = viewRay();
    EXPECT_THROW((void)inscatterFromPointTable(m, point(), ray), std::invalid_argument);
    Medium isotropic = m;
    isotropic.betaR = glm::dvec3(0.0);
    isotropic.miePhase = Medium::Isotropic;
    EXPECT_THROW((void)pointArctanClosedForm(isotropic, point(), ray), std::invalid_argument);
    EXPECT_THROW((void)simplifiedClosedForm(isotropic, point(), ray, 0.01, 1.0),
                 std::invalid_argument);
}

}  // namespace
}  // namespace ls::ref
