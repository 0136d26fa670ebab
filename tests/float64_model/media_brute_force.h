#pragma once
// Brute-force integrals of the non-uniform medium for the tests: dense midpoint rules over m(x)
// sampled point by point, sharing nothing with the model's closed forms, kink lists or adaptive
// quadrature. Each rule is split where the test knows the integrand jumps (every plane of the
// medium: base height, box faces, fade and centre planes), so that its
// error is the midpoint rule's O(h^2) and not the O(h) a jump between two samples would cost.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "float64_model/density.h"
#include "float64_model/ray.h"

namespace ls::ref::test {

// The t in (lo, hi) where origin + t dir crosses any plane of the medium; with lo and hi, sorted.
inline std::vector<double> planeCrossings(const Density& d, const glm::dvec3& origin,
                                          const glm::dvec3& dir, double lo, double hi) {
    std::vector<double> t{lo, hi};
    auto plane = [&](const glm::dvec3& normal, double offset) {  // dot(normal, x) = offset
        const double rate = glm::dot(normal, dir);
        if (rate == 0.0) return;
        const double at = (offset - glm::dot(normal, origin)) / rate;
        if (at > lo && at < hi) t.push_back(at);
    };
    if (d.heightFog) plane({0.0, 1.0, 0.0}, d.heightFog->baseHeight);
    for (const FogBox& b : d.volumes) {
        for (int j = 0; j < 3; ++j) {
            const double c = glm::dot(b.axes[j], b.center), a = b.halfExtents[j];
            for (double offset : {-a, a, -(a - b.fade), a - b.fade, 0.0})
                plane(b.axes[j], c + offset);
        }
    }
    std::sort(t.begin(), t.end());
    return t;
}

// Midpoint rule for the integral of m over t in [lo, hi] of origin + t dir (dir unit), with
// `panels` panels spread over the pieces between plane crossings in proportion to their length.
inline double bruteOpticalDepth(const Density& d, const glm::dvec3& origin, const glm::dvec3& dir,
                                double lo, double hi, int panels) {
    if (!(hi > lo)) return 0.0;
    const std::vector<double> cuts = planeCrossings(d, origin, dir, lo, hi);
    // A long double sum: 1e5 and more terms would otherwise round the total by 1e-11.
    long double sum = 0.0L;
    for (std::size_t i = 1; i < cuts.size(); ++i) {
        const double a = cuts[i - 1], b = cuts[i];
        const int n = std::max(1, static_cast<int>(std::ceil(panels * (b - a) / (hi - lo))));
        const double h = (b - a) / n;
        for (int k = 0; k < n; ++k) sum += d.at(origin + (a + (k + 0.5) * h) * dir) * h;
    }
    return static_cast<double>(sum);
}

inline double bruteOpticalDepth(const Density& d, const glm::dvec3& from, const glm::dvec3& to,
                                int panels) {
    const double length = glm::length(to - from);
    if (!(length > 0.0)) return 0.0;
    return bruteOpticalDepth(d, from, (to - from) / length, 0.0, length, panels);
}

}  // namespace ls::ref::test
