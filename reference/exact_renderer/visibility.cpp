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

std::optional<OcclusionQuery> LightVisibility::shadowRay(const glm::dvec3& p) const {
    if (light_.type == ls::ref::Light::Directional)
        return OcclusionQuery{PreparedRay(p, towardLight_), offset_,
                              std::numeric_limits<double>::infinity()};
    const glm::dvec3 toLight = light_.position - p;
    const double distance = glm::length(toLight);
    if (!(distance > 2.0 * offset_)) return std::nullopt;  // at the light (or NaN)
    return OcclusionQuery{PreparedRay(p, toLight / distance), offset_, distance - offset_};
}

bool LightVisibility::visible(const glm::dvec3& p) const {
    const std::optional<OcclusionQuery> q = shadowRay(p);
    return !q || !bvh_->anyHit(q->ray, q->tMin, q->tMax);
}

void LightVisibility::visible(std::span<const glm::dvec3> points, std::span<uint8_t> out) const {
    thread_local std::vector<OcclusionQuery> queries;
    thread_local std::vector<std::size_t> asked;  // the point of each query
    thread_local std::vector<uint8_t> hits;
    queries.clear();
    asked.clear();
    for (std::size_t i = 0; i < points.size(); ++i) {
        out[i] = 1;
        if (std::optional<OcclusionQuery> q = shadowRay(points[i])) {
            queries.push_back(*q);
            asked.push_back(i);
        }
    }
    hits.resize(queries.size());
    bvh_->anyHit(queries, hits);
    for (std::size_t k = 0; k < queries.size(); ++k) out[asked[k]] = hits[k] ? 0 : 1;
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
    std::vector<glm::dvec3> positions;
    std::vector<uint8_t> grid;  // V at each of `points`, asked of the BVH together
    for (const ls::ref::Interval& in : volume) {
        points.assign(1, in.begin);
        const int first = static_cast<int>(std::floor(in.begin / spacing)) + 1;
        for (int k = std::max(first, 1); k < samples; ++k) {
            const double s = k * spacing;
            if (s >= in.end) break;
            if (s > in.begin) points.push_back(s);
        }
        points.push_back(in.end);

        positions.resize(points.size());
        for (std::size_t i = 0; i < points.size(); ++i)
            positions[i] = ray.origin + std::min(points[i], lastPoint) * ray.direction;
        grid.resize(points.size());
        visibility.visible(positions, grid);

        bool previous = grid[0] != 0;
        double start = in.begin;
        for (std::size_t i = 1; i < points.size(); ++i) {
            const bool v = grid[i] != 0;
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
