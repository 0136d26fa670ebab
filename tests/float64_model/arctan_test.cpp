#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "float64_model/closed_forms.h"
#include "float64_model/inscatter_integral.h"
#include "float64_model/ray_geometry.h"
#include "test_util.h"

namespace ls::ref {
namespace {

using test::near3;

// Quadrature of 1/((s + b)^2 + w^2) over [0, len], meshed around the peak at s = -b.
double quadratureOfLorentzian(double b, double w, double len) {
    std::vector<double> cuts{-b};
    appendGeometricMesh(cuts, -b, w, 1.0, 0.0, len);
    appendGeometricMesh(cuts, -b, w, -1.0, 0.0, len);
    const Interval whole{0.0, len};
    QuadOptions tight;
    tight.relTol = 1e-13;
    const QuadResult r =
        integrateAdaptive([&](double s) { return glm::dvec3(1.0 / ((s + b) * (s + b) + w * w)); },
                          splitAt({&whole, 1}, cuts), tight);
    EXPECT_TRUE(r.converged);
    return r.value.x;
}

TEST(Arctan, IntegralMatchesQuadrature) {
    for (double b : {-1e7, -300.0, -50.0, -10.0, -0.3, 0.0, 0.2, 7.0, 1e3, 1e8}) {
        for (double w : {0.05, 1.0, 40.0}) {
            for (double len : {0.01, 20.0, 1e4}) {
                const double expected = quadratureOfLorentzian(b, w, len);
                EXPECT_NEAR(arctanIntegral(b, w, len) / expected, 1.0, 1e-12)
                    << "b=" << b << " w=" << w << " len=" << len;
            }
        }
    }
}

// A ray through the light's centre, camera 5 m in front of it: 2 atan(5/r0)/r0 for S = 10.
TEST(Arctan, RayThroughTheLight) {
    const double r0 = 0.05;
    EXPECT_NEAR(arctanIntegral(-5.0, r0, 10.0) / (2.0 * std::atan(5.0 / r0) / r0), 1.0, 1e-15);
}

// A light far behind the camera: both arctangents are within 1e-9 of pi/2. For u >> w the
// integral is 1/b - 1/(b + len) up to a relative w^2/b^2 (here 1e-19), evaluated in long double as
// len / (b (b + len)).
TEST(Arctan, FarBehindTheCameraKeepsItsDigits) {
    for (double b : {1e6, 1e8, 1e10}) {
        const double w = 0.05;
        const double len = 10.0;
        const long double lb = b;
        const long double expected = len / (lb * (lb + len));
        const double ours = arctanIntegral(b, w, len);
        EXPECT_NEAR(ours / static_cast<double>(expected), 1.0, 1e-14) << b;
        // The textbook difference of arctangents fails this very check.
        const double naive = (std::atan((len + b) / w) - std::atan(b / w)) / w;
        EXPECT_GT(std::abs(naive / static_cast<double>(expected) - 1.0), 1e-6) << b;
        // Mirror image: the light far beyond the end of the ray.
        EXPECT_NEAR(arctanIntegral(-b - len, w, len) / static_cast<double>(expected), 1.0, 1e-14);
    }
}

// With betaT = 0 (sigmaA = -betaM cancels extinction exactly) and an isotropic total phase, the
// model integral is seed 001's closed form; quadrature of the full model must agree.
Medium noExtinctionIsotropic() {
    Medium m;
    m.miePhase = Medium::Isotropic;
    m.betaM = {1e-3, 2e-2, 0.0};
    m.sigmaA = -m.betaM;
    return m;
}

struct Geometry {
    const char* name;
    glm::dvec3 camera;
    glm::dvec3 light;
    double length;
};

const std::vector<Geometry> kGeometries = {
    {"beside", {0.0, 0.0, 0.0}, {2.0, 1.0, -30.0}, 100.0},
    {"through the light", {0.0, 0.0, 0.0}, {0.0, 0.0, -30.0}, 100.0},
    {"behind the camera", {0.0, 0.0, 0.0}, {0.5, 0.0, 40.0}, 100.0},
    {"far behind", {0.0, 0.0, 0.0}, {0.5, 0.0, 1e5}, 100.0},
    {"at the camera", {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 100.0},
    {"beyond the end", {0.0, 0.0, 0.0}, {0.3, 0.0, -500.0}, 100.0},
    {"long ray", {1.0, 2.0, 3.0}, {1.0, 3.0, -2.0}, 1e6},
};

TEST(Arctan, ClosedFormMatchesModelWithoutExtinction) {
    const Medium m = noExtinctionIsotropic();
    for (const Geometry& geo : kGeometries) {
        Light l;
        l.position = geo.light;
        l.intensity = {5.0, 3.0, 1.0};
        const Ray ray{geo.camera, {0.0, 0.0, -1.0}, geo.length};
        const QuadResult num = integrateInscatter(m, l, ray);
        ASSERT_TRUE(num.converged) << geo.name;
        EXPECT_TRUE(near3(pointArctanClosedForm(m, l, ray), num.value, 1e-9)) << geo.name;
        EXPECT_EQ(pointArctanClosedForm(m, l, ray).z, 0.0);
        const std::vector<Interval> lit{{1.0, 25.0}, {29.0, 31.0}, {60.0, 1e9}};
        const QuadResult numLit = integrateInscatter(m, l, ray, lit);
        ASSERT_TRUE(numLit.converged) << geo.name;
        EXPECT_TRUE(near3(pointArctanClosedForm(m, l, ray, lit), numLit.value, 1e-9)) << geo.name;
    }
}

// With extinction the closed form over-estimates by at most betaT (2 S + |q|) relatively.
TEST(Arctan, ThinMediumStaysWithinTheExtinctionBound) {
    Medium m;
    m.miePhase = Medium::Isotropic;
    m.betaM = {1e-7, 1e-6, 1e-5};
    Light l;
    l.position = {1.0, 0.0, -20.0};
    const Ray ray{{0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 60.0};
    const glm::dvec3 closed = pointArctanClosedForm(m, l, ray);
    const glm::dvec3 num = integrateInscatter(m, l, ray).value;
    const double pathBound = 2.0 * 60.0 + glm::length(l.position);
    for (int c = 0; c < 3; ++c) {
        const double rel = (closed[c] - num[c]) / num[c];
        EXPECT_GT(rel, 0.0);
        EXPECT_LT(rel, m.betaT()[c] * pathBound);
        EXPECT_GT(rel, 0.1 * m.betaT()[c] * pathBound);  // and the bound is not vacuous
    }
}

TEST(Arctan, RejectsWhatItDoesNotCover) {
    Medium m = noExtinctionIsotropic();
    Light l;
    const Ray ray{{}, {0.0, 0.0, -1.0}, 1.0};
    m.betaR = {1e-3, 0.0, 0.0};
    EXPECT_THROW((void)pointArctanClosedForm(m, l, ray), std::invalid_argument);
    m = noExtinctionIsotropic();
    m.miePhase = Medium::CornetteShanks;
    EXPECT_THROW((void)pointArctanClosedForm(m, l, ray), std::invalid_argument);
    l.type = Light::Directional;
    EXPECT_THROW((void)pointArctanClosedForm(noExtinctionIsotropic(), l, ray),
                 std::invalid_argument);
}

}  // namespace
}  // namespace ls::ref
