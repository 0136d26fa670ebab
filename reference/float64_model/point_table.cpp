#include "point_table.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include "ray_geometry.h"

namespace ls::ref {
namespace {

constexpr double kTailFraction = 1e-16;
constexpr double kGrowth = 16.0;
constexpr int kMaxGrowthSteps = 200;  // 16^200 overflows long before; only a guard

struct TableIntegrand {
    const Medium& medium;
    glm::dvec3 intensity;
    glm::dvec3 beta;
    double h;
    double s;
    double r0;

    glm::dvec3 operator()(double x) const {
        const double r = std::sqrt(h * h + x * x);
        const double cosT = r > 0.0 ? -x / r : 0.0;
        // One exponential of the summed path keeps each factor from underflowing on its own.
        return intensity * medium.P(cosT) * glm::exp(-beta * ((x - s) + r)) / (r * r + r0 * r0);
    }
};

// Pieces of [lo, hi] split where the integrand changes scale: the geometric mesh around the
// peak at x = 0 (width w) and the extinction mesh from the table's start s.
std::vector<Interval> tablePieces(double lo, double hi, double s, double w, double betaMax) {
    std::vector<double> cuts{0.0};
    appendGeometricMesh(cuts, 0.0, w, 1.0, lo, hi);
    appendGeometricMesh(cuts, 0.0, w, -1.0, lo, hi);
    if (betaMax > 0.0) appendGeometricMesh(cuts, s, 1.0 / (16.0 * betaMax), 1.0, lo, hi);
    const Interval whole{lo, hi};
    return splitAt({&whole, 1}, std::move(cuts));
}

bool tailNegligible(const glm::dvec3& bound, const glm::dvec3& sum) {
    for (int c = 0; c < 3; ++c) {
        if (!(bound[c] <= kTailFraction * std::abs(sum[c]))) return false;
    }
    return true;
}

}  // namespace

PointRayFrame pointRayFrame(const Light& light, const Ray& ray) {
    return {lineDistance(ray, light.position),
            glm::dot(ray.direction, ray.origin - light.position)};
}

glm::dvec3 pointTable(const Medium& medium, const Light& light, double h, double s,
                      const QuadOptions& options) {
    // The table's coordinates hold only the ray's distance from the light: a medium that varies
    // from point to point has no such table (docs/model.md).
    if (!medium.density.unit())
        throw std::invalid_argument("pointTable: needs a homogeneous medium (m = 1)");
    if (!std::isfinite(h) || !std::isfinite(s)) return glm::dvec3(0.0);
    const glm::dvec3 beta = medium.betaT();
    const double betaMax = std::max({beta.x, beta.y, beta.z});
    const double r0 = effectiveRadius(light);
    const double w = std::sqrt(h * h + r0 * r0);
    const TableIntegrand f{medium, light.intensity, beta, h, s, r0};

    double end = std::max(s, 0.0) + 16.0 * std::max(w, betaMax > 0.0 ? 1.0 / betaMax : 0.0);
    glm::dvec3 sum = integrateAdaptive(f, tablePieces(s, end, s, w, betaMax), options).value;
    // Beyond X > max(s, 0): sqrt(h^2 + x^2) >= x and h^2 + x^2 + r0^2 >= x^2, so the rest is at
    // most I maxP exp(-betaT (2X - s)) times the integral of 1/x^2 from X, which is 1/X.
    const glm::dvec3 peak = light.intensity * medium.maxP();
    for (int step = 0; step < kMaxGrowthSteps; ++step) {
        const glm::dvec3 bound = peak * glm::exp(-beta * (2.0 * end - s)) / end;
        if (tailNegligible(bound, sum)) break;
        const double next = end * kGrowth;
        sum += integrateAdaptive(f, tablePieces(end, next, s, w, betaMax), options).value;
        end = next;
    }
    return sum;
}

glm::dvec3 pointTableSegment(const Medium& medium, const Light& light, double h, double sCamera,
                             double sa, double sb, const QuadOptions& options) {
    if (!(sb > sa)) return glm::dvec3(0.0);
    const glm::dvec3 beta = medium.betaT();
    return glm::exp(-beta * (sa - sCamera)) * pointTable(medium, light, h, sa, options) -
           glm::exp(-beta * (sb - sCamera)) * pointTable(medium, light, h, sb, options);
}

glm::dvec3 inscatterFromPointTable(const Medium& medium, const Light& light, const Ray& ray,
                                   std::span<const Interval> lit, const QuadOptions& options) {
    if (light.type == Light::Directional) {
        throw std::invalid_argument("inscatterFromPointTable: needs a point or spot light");
    }
    if (!medium.density.unit())
        throw std::invalid_argument("inscatterFromPointTable: needs a homogeneous medium (m = 1)");
    const std::optional<Ray> maybeUnit = unitRay(ray);
    if (!maybeUnit) return glm::dvec3(0.0);
    const Ray& unit = *maybeUnit;
    const PointRayFrame frame = pointRayFrame(light, unit);
    const glm::dvec3 beta = medium.betaT();
    glm::dvec3 sum(0.0);
    for (const Interval& in :
         intersectIntervals(normalizeIntervals(lit, unit.length), spotLitIntervals(light, unit))) {
        // Same as pointTableSegment, with sa - sCamera taken as the camera distance itself
        // rather than recovered from a difference.
        sum += glm::exp(-beta * in.begin) *
                   pointTable(medium, light, frame.h, frame.sCamera + in.begin, options) -
               glm::exp(-beta * in.end) *
                   pointTable(medium, light, frame.h, frame.sCamera + in.end, options);
    }
    return sum;
}

glm::dvec3 inscatterFromPointTable(const Medium& medium, const Light& light, const Ray& ray,
                                   const QuadOptions& options) {
    const Interval whole{0.0, ray.length};
    return inscatterFromPointTable(medium, light, ray, {&whole, 1}, options);
}

}  // namespace ls::ref
