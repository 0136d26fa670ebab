#include "optical_depth.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "box_crossings.h"

namespace ls::ref {

double meanDecay(double x) {
    // -expm1(-x) is exact for tiny x, so the quotient needs no series; only x = 0 needs its limit.
    return x == 0.0 ? 1.0 : -std::expm1(-x) / x;
}

double heightOpticalDepth(const HeightFog& fog, const glm::dvec3& origin,
                          const glm::dvec3& direction, double t0, double t1) {
    if (!(t1 > t0)) return 0.0;
    const double length = t1 - t0;
    const double k = fog.falloff;
    if (k == 0.0) return length;
    const double h0 = fog.baseHeight;
    const double ya = origin.y + t0 * direction.y, yb = origin.y + t1 * direction.y;
    const double yLow = std::min(ya, yb), yHigh = std::max(ya, yb);
    const double slope = std::abs(direction.y);
    if (yHigh <= h0) return length;
    if (yLow >= h0) return std::exp(-k * (yLow - h0)) * length * meanDecay(k * slope * length);
    // The segment crosses h0 (so direction.y != 0); above it the lower end is at h0 itself.
    const double tCross = (h0 - origin.y) / direction.y;
    const double above = std::clamp(direction.y > 0.0 ? t1 - tCross : tCross - t0, 0.0, length);
    return (length - above) + above * meanDecay(k * slope * above);
}

double boxOpticalDepth(const FogBox& box, const glm::dvec3& origin, const glm::dvec3& direction,
                       double t0, double t1) {
    if (!(t1 > t0)) return 0.0;
    if (!(box.fade > 0.0)) {
        const std::optional<Interval> span = boxSpan(box, origin, direction);
        if (!span) return 0.0;
        return std::max(0.0, std::min(span->end, t1) - std::max(span->begin, t0));
    }
    const std::vector<double> kinks = boxWeightKinks(box, origin, direction);
    if (kinks.empty()) return 0.0;
    // The weight in the box's own coordinates, where the line is q + t w.
    const glm::dvec3 q = box.local(origin);
    const glm::dvec3 w{glm::dot(direction, box.axes[0]), glm::dot(direction, box.axes[1]),
                       glm::dot(direction, box.axes[2])};
    auto weight = [&](double t) {
        double b = 1.0;
        for (int j = 0; j < 3; ++j)
            b *= std::clamp((box.halfExtents[j] - std::abs(q[j] + t * w[j])) / box.fade, 0.0, 1.0);
        return b;
    };
    double sum = 0.0;
    for (std::size_t i = 1; i < kinks.size(); ++i) {
        const double a = std::max(kinks[i - 1], t0), b = std::min(kinks[i], t1);
        if (!(b > a)) continue;
        sum += (b - a) / 6.0 * (weight(a) + 4.0 * weight(0.5 * (a + b)) + weight(b));
    }
    return sum;
}

double opticalDepth(const Density& density, const Ray& ray, double s0, double s1) {
    if (!(s1 > s0)) return 0.0;
    double tau = density.base *
                 (density.heightFog
                      ? heightOpticalDepth(*density.heightFog, ray.origin, ray.direction, s0, s1)
                      : s1 - s0);
    for (const FogBox& box : density.volumes) {
        if (box.density > 0.0)
            tau += box.density * boxOpticalDepth(box, ray.origin, ray.direction, s0, s1);
    }
    return tau;
}

double opticalDepth(const Density& density, const glm::dvec3& a, const glm::dvec3& b) {
    const double length = glm::length(b - a);
    if (!(length > 0.0)) return 0.0;
    return opticalDepth(density, Ray{a, (b - a) / length, length}, 0.0, length);
}

}  // namespace ls::ref
