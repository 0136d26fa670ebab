// Seed 004's simplified light model (2.12-2.17) against numerical quadrature of its own integrand,
// and its relation to the model: with a1 = 1 and a0 = r0^2 it is seed 001's closed form.
#include <cmath>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "float64_model/closed_forms.h"
#include "float64_model/gauss_kronrod.h"
#include "float64_model/light.h"
#include "float64_model/ray_geometry.h"
#include "test_util.h"

namespace ls::ref {
namespace {

Medium isotropicHaze() {
    Medium m;
    m.betaR = {0.0, 0.0, 0.0};
    m.betaM = {0.02, 0.03, 0.04};
    m.miePhase = Medium::Isotropic;
    return m;
}

Light rangedSpot() {
    Light l;
    l.type = Light::Spot;
    l.position = {0.0, 4.0, 0.0};
    l.direction = {0.0, -1.0, 0.0};
    l.intensity = {30.0, 25.0, 20.0};
    l.outerAngle = l.innerAngle = 0.5;
    l.range = 9.0;
    return l;
}

// The seed's integrand (2.12-2.15): sigma_s I(Omega) / (4 pi (a1 r^2 + a0)), by quadrature.
glm::dvec3 simplifiedByQuadrature(const Medium& m, const Light& l, const Ray& ray, double a0,
                                  double a1) {
    // Integrated over the spot's lit intervals, so that the cone's edges are ends, not kinks
    // inside.
    const std::vector<Interval> lit = spotLitIntervals(l, ray);
    const QuadResult r = integrateAdaptive(
        [&](double z) {
            const glm::dvec3 p = ray.origin + z * ray.direction;
            const glm::dvec3 d = p - l.position;
            return l.intensity * (m.betaR + m.betaM) *
                   (kIsotropicPhase / (a1 * glm::dot(d, d) + a0));
        },
        lit);
    return r.value;
}

}  // namespace

TEST(SimplifiedModel, ClosedFormMatchesQuadratureOfItsIntegrand) {
    const Medium m = isotropicHaze();
    const Light l = rangedSpot();
    for (double a0 : {0.0025, 0.5, 4.0})
        for (double a1 : {0.5, 1.0, 3.0})
            for (const Ray& ray :
                 {Ray{{-6.0, 1.0, 0.5}, glm::normalize(glm::dvec3(1.0, 0.02, 0.0)), 12.0},
                  Ray{{0.3, 8.0, 0.0}, glm::normalize(glm::dvec3(0.0, -1.0, 0.01)), 10.0},
                  Ray{{5.0, 0.5, -5.0}, glm::normalize(glm::dvec3(-1.0, 0.1, 1.0)), 20.0}}) {
                const glm::dvec3 closed = simplifiedClosedForm(m, l, ray, a0, a1);
                const glm::dvec3 quad = simplifiedByQuadrature(m, l, ray, a0, a1);
                for (int c = 0; c < 3; ++c) {
                    EXPECT_GT(quad[c], 0.0);
                    EXPECT_NEAR(closed[c], quad[c], 1e-7 * quad[c]) << "a0 " << a0 << " a1 " << a1;
                }
            }
}

TEST(SimplifiedModel, WithA1OneAndA0R0SquaredItIsSeed001sClosedForm) {
    const Medium m = isotropicHaze();
    Light l = rangedSpot();
    l.r0 = 0.05;
    const Ray ray{{-6.0, 1.0, 0.5}, glm::normalize(glm::dvec3(1.0, 0.3, 0.0)), 12.0};
    const glm::dvec3 seed004 = simplifiedClosedForm(m, l, ray, l.r0 * l.r0, 1.0);
    const glm::dvec3 seed001 = pointArctanClosedForm(m, l, ray);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(seed004[c], seed001[c], 1e-12 * seed001[c]);
    EXPECT_THROW((void)simplifiedClosedForm(m, l, ray, 0.1, 0.0), std::invalid_argument);
    l.type = Light::Directional;
    EXPECT_THROW((void)simplifiedClosedForm(m, l, ray, 0.1, 1.0), std::invalid_argument);
}

}  // namespace ls::ref
