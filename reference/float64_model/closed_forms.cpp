#include "closed_forms.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include "optical_depth.h"
#include "ray_geometry.h"

namespace ls::ref {
namespace {

// Below this beta * length the series 1 - x/2 + x^2/6 is exact to double precision and, unlike
// expm1(-x)/beta, stays exact when beta is subnormal.
constexpr double kSeriesLimit = 1e-5;

}  // namespace

double attenuatedLength(double beta, double a, double b) {
    if (!(b > a)) return 0.0;
    const double length = b - a;
    const double x = beta * length;
    const double fromA =
        x < kSeriesLimit ? length * (1.0 - x * (0.5 - x / 6.0)) : -std::expm1(-x) / beta;
    return std::exp(-beta * a) * fromA;
}

glm::dvec3 attenuatedLength(const glm::dvec3& beta, double a, double b) {
    return {attenuatedLength(beta.x, a, b), attenuatedLength(beta.y, a, b),
            attenuatedLength(beta.z, a, b)};
}

glm::dvec3 directionalClosedForm(const Medium& medium, const Light& light, const Ray& ray) {
    const Interval whole{0.0, ray.length};
    return directionalClosedForm(medium, light, ray, {&whole, 1});
}

glm::dvec3 directionalClosedForm(const Medium& medium, const Light& light, const Ray& ray,
                                 std::span<const Interval> lit) {
    if (light.type != Light::Directional) {
        throw std::invalid_argument("directionalClosedForm: the light is not directional");
    }
    const std::optional<Ray> maybeUnit = unitRay(ray);
    if (!maybeUnit) return glm::dvec3(0.0);
    const Ray& unit = *maybeUnit;
    const glm::dvec3 beta = medium.betaT();
    glm::dvec3 sum(0.0);
    if (!medium.density.unit()) {
        // dT/ds = -betaT m T, so a run [a, b] gives T(a) times the integral of exp(-betaT u) over
        // the optical depth u in [0, dtau], dtau taken directly (never T(a) - T(b)).
        for (const Interval& in : normalizeIntervals(lit, unit.length)) {
            const double before = opticalDepth(medium.density, unit, 0.0, in.begin);
            const double run = opticalDepth(medium.density, unit, in.begin, in.end);
            sum += glm::exp(-beta * before) * attenuatedLength(beta, 0.0, run);
        }
    } else {
        for (const Interval& in : normalizeIntervals(lit, unit.length)) {
            sum += attenuatedLength(beta, in.begin, in.end);
        }
    }
    // cosTheta ignores the point for a directional light.
    return light.intensity * medium.P(cosTheta(light, unit.direction, unit.origin)) * sum;
}

double arctanIntegral(double b, double w, double length) {
    if (!(length > 0.0)) return 0.0;
    const double u0 = b;
    const double u1 = b + length;
    double angle;
    if (u0 >= 0.0 || u1 <= 0.0) {
        // tan(atan x - atan y) = (x - y) / (1 + x y), and 1 + x y >= 1 here; atan2 keeps the
        // angle right however small it gets.
        angle = std::atan2(length * w, w * w + u0 * u1);
    } else {
        // Opposite signs: the two arctangents add in magnitude, nothing cancels.
        angle = std::atan(u1 / w) - std::atan(u0 / w);
    }
    return angle / w;
}

glm::dvec3 pointArctanClosedForm(const Medium& medium, const Light& light, const Ray& ray) {
    const Interval whole{0.0, ray.length};
    return pointArctanClosedForm(medium, light, ray, {&whole, 1});
}

glm::dvec3 pointArctanClosedForm(const Medium& medium, const Light& light, const Ray& ray,
                                 std::span<const Interval> lit) {
    if (light.type == Light::Directional) {
        throw std::invalid_argument("pointArctanClosedForm: needs a point or spot light");
    }
    if (!medium.density.unit()) {
        throw std::invalid_argument("pointArctanClosedForm: needs a homogeneous medium (m = 1)");
    }
    if (medium.betaR != glm::dvec3(0.0) || medium.miePhase != Medium::Isotropic) {
        throw std::invalid_argument(
            "pointArctanClosedForm: needs an isotropic total phase (betaR = 0, isotropic Mie)");
    }
    const std::optional<Ray> maybeUnit = unitRay(ray);
    if (!maybeUnit) return glm::dvec3(0.0);
    const Ray& unit = *maybeUnit;
    const double b = glm::dot(unit.direction, unit.origin - light.position);
    const double h = lineDistance(unit, light.position);
    const double r0 = effectiveRadius(light);
    const double w = std::sqrt(h * h + r0 * r0);
    const std::vector<Interval> lit01 =
        intersectIntervals(normalizeIntervals(lit, unit.length), spotLitIntervals(light, unit));
    double sum = 0.0;
    // A lit interval [s_in, s_out] is the same integral for a ray starting s_in further on.
    for (const Interval& in : lit01) sum += arctanIntegral(b + in.begin, w, in.end - in.begin);
    return light.intensity * medium.betaM * (kIsotropicPhase * sum);
}

glm::dvec3 simplifiedClosedForm(const Medium& medium, const Light& light, const Ray& ray, double a0,
                                double a1) {
    const Interval whole{0.0, ray.length};
    return simplifiedClosedForm(medium, light, ray, {&whole, 1}, a0, a1);
}

glm::dvec3 simplifiedClosedForm(const Medium& medium, const Light& light, const Ray& ray,
                                std::span<const Interval> lit, double a0, double a1) {
    if (light.type == Light::Directional)
        throw std::invalid_argument("simplifiedClosedForm: needs a point or spot light");
    if (!(a1 > 0.0) || !(a0 >= 0.0))
        throw std::invalid_argument("simplifiedClosedForm: needs a1 > 0 and a0 >= 0");
    if (!medium.density.unit())
        throw std::invalid_argument("simplifiedClosedForm: needs a homogeneous medium (m = 1)");
    const std::optional<Ray> maybeUnit = unitRay(ray);
    if (!maybeUnit) return glm::dvec3(0.0);
    const Ray& unit = *maybeUnit;
    const double b = glm::dot(unit.direction, unit.origin - light.position);  // -z_s of (2.16)
    const double h = lineDistance(unit, light.position);                      // r_0 of (2.16)
    const double w = std::sqrt(h * h + a0 / a1);
    const std::vector<Interval> lit01 =
        intersectIntervals(normalizeIntervals(lit, unit.length), spotLitIntervals(light, unit));
    double sum = 0.0;
    for (const Interval& in : lit01) sum += arctanIntegral(b + in.begin, w, in.end - in.begin);
    return light.intensity * (medium.betaR + medium.betaM) * (kIsotropicPhase * sum / a1);
}

}  // namespace ls::ref
