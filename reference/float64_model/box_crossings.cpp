#include "box_crossings.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace ls::ref {

std::optional<Interval> boxSpan(const FogBox& box, const glm::dvec3& origin,
                                const glm::dvec3& direction) {
    const glm::dvec3 q = box.local(origin);
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    for (int j = 0; j < 3; ++j) {
        const double a = box.halfExtents[j];
        const double w = glm::dot(direction, box.axes[j]);
        if (w == 0.0) {
            if (!(std::abs(q[j]) <= a)) return std::nullopt;
            continue;
        }
        const double t0 = (-a - q[j]) / w, t1 = (a - q[j]) / w;
        lo = std::max(lo, std::min(t0, t1));
        hi = std::min(hi, std::max(t0, t1));
    }
    if (!(lo <= hi)) return std::nullopt;
    return Interval{lo, hi};
}

std::vector<double> boxWeightKinks(const FogBox& box, const glm::dvec3& origin,
                                   const glm::dvec3& direction) {
    const std::optional<Interval> span = boxSpan(box, origin, direction);
    if (!span) return {};
    std::vector<double> kinks{span->begin, span->end};
    if (box.fade > 0.0) {
        const glm::dvec3 q = box.local(origin);
        for (int j = 0; j < 3; ++j) {
            const double w = glm::dot(direction, box.axes[j]);
            if (w == 0.0) continue;  // the factor is constant along the line
            const double inner = box.halfExtents[j] - box.fade;
            auto add = [&](double plane) {
                const double t = (plane - q[j]) / w;
                if (t > span->begin && t < span->end) kinks.push_back(t);
            };
            if (inner > 0.0) {
                add(-inner);
                add(inner);
            } else {
                add(0.0);
            }
        }
    }
    std::sort(kinks.begin(), kinks.end());
    return kinks;
}

}  // namespace ls::ref
