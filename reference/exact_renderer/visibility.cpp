#include "visibility.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "float64_model/ray_geometry.h"

namespace host::reference {

LightVisibility::LightVisibility(const Bvh& bvh, const ls::ref::Light& light)
    : bvh_(&bvh), light_(light), offset_(kShadowOffset * bvh.coordinateScale()) {
    if (light.type == ls::ref::Light::Directional) towardLight_ = -glm::normalize(light.direction);
}

bool LightVisibility::visible(const glm::dvec3& p) const {
    if (light_.type == ls::ref::Light::Directional) {
        return !bvh_->anyHit(PreparedRay(p, towardLight_), offset_,
                             std::numeric_limits<double>::infinity());
    }
    const glm::dvec3 toLight = light_.position - p;
    const double distance = glm::length(toLight);
    if (!(distance > 2.0 * offset_)) return true;  // at the light (or NaN): nothing in between
    return !bvh_->anyHit(PreparedRay(p, toLight / distance), offset_, distance - offset_);
}

namespace {

// Where V changes between lo (value vLo) and hi (the other value), to within tol.
template <class Visible>
double bisect(const Visible& visible, double lo, double hi, bool vLo, double tol) {
    while (hi - lo > tol) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;  // adjacent doubles: nothing finer to find
        (visible(mid) == vLo ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

std::vector<ls::ref::Interval> litIntervals(const LightVisibility& visibility,
                                            const ls::ref::Light& light, const ls::ref::Ray& ray,
                                            const LitSearch& search) {
    std::vector<ls::ref::Interval> volume = ls::ref::spotLitIntervals(light, ray);
    if (!search.shadows || volume.empty()) return volume;
    const double length = ray.length;
    const double tol = search.relTol * length;
    const double lastPoint = length - tol;
    auto visible = [&](double s) {
        return visibility.visible(ray.origin + std::min(s, lastPoint) * ray.direction);
    };
    const int samples = std::max(search.samples, 1);
    const double spacing = length / samples;

    std::vector<ls::ref::Interval> lit;
    std::vector<double> points;
    for (const ls::ref::Interval& in : volume) {
        points.assign(1, in.begin);
        const int first = static_cast<int>(std::floor(in.begin / spacing)) + 1;
        for (int k = std::max(first, 1); k < samples; ++k) {
            const double s = k * spacing;
            if (s >= in.end) break;
            if (s > in.begin) points.push_back(s);
        }
        points.push_back(in.end);

        bool previous = visible(points[0]);
        double start = in.begin;
        for (std::size_t i = 1; i < points.size(); ++i) {
            const bool v = visible(points[i]);
            if (v == previous) continue;
            const double edge = bisect(visible, points[i - 1], points[i], previous, tol);
            if (v) {
                start = edge;
            } else {
                lit.push_back({start, edge});
            }
            previous = v;
        }
        if (previous) lit.push_back({start, in.end});
    }
    return ls::ref::normalizeIntervals(lit, length);
}

}  // namespace host::reference
