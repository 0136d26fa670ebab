#include "ray_geometry.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace ls::ref {
namespace {

constexpr double kMeshRatio = 4.0;

// Real roots of a s^2 + b s + c = 0, without the cancellation of the textbook formula.
std::vector<double> solveQuadratic(double a, double b, double c) {
    std::vector<double> roots;
    if (a == 0.0) {
        if (b != 0.0) roots.push_back(-c / b);
        return roots;
    }
    const double disc = b * b - 4.0 * a * c;
    if (!(disc >= 0.0)) return roots;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    if (q == 0.0) {
        roots.push_back(0.0);  // b == 0 and c == 0: a double root at 0
        return roots;
    }
    roots.push_back(q / a);
    roots.push_back(c / q);
    std::sort(roots.begin(), roots.end());
    return roots;
}

}  // namespace

std::optional<Ray> unitRay(const Ray& ray) {
    const double dirLength = glm::length(ray.direction);
    if (!(dirLength > 0.0) || !std::isfinite(dirLength) || !std::isfinite(ray.length)) {
        return std::nullopt;
    }
    Ray unit = ray;
    unit.direction /= dirLength;
    return unit;
}

double closestApproach(const Ray& ray, const glm::dvec3& p) {
    return glm::dot(ray.direction, p - ray.origin);
}

double lineDistance(const Ray& ray, const glm::dvec3& p) {
    return glm::length(glm::cross(ray.direction, ray.origin - p));
}

std::vector<double> raySphereCrossings(const Ray& ray, const glm::dvec3& centre, double radius) {
    const double mid = closestApproach(ray, centre);
    const double h = lineDistance(ray, centre);
    // (R - h)(R + h) rather than R^2 - h^2 keeps a grazing ray's half-chord accurate.
    const double halfChord2 = (radius - h) * (radius + h);
    if (!(halfChord2 >= 0.0) || !std::isfinite(halfChord2)) return {};
    const double halfChord = std::sqrt(halfChord2);
    return {mid - halfChord, mid + halfChord};
}

std::vector<double> rayConeCrossings(const Ray& ray, const glm::dvec3& apex, const glm::dvec3& axis,
                                     double halfAngle) {
    const glm::dvec3 a = glm::normalize(axis);
    const glm::dvec3 q = ray.origin - apex;
    const double c2 = std::cos(halfAngle) * std::cos(halfAngle);
    const double va = glm::dot(ray.direction, a);
    const double qa = glm::dot(q, a);
    // (d.a)^2 = cos^2(alpha) |d|^2 with d = q + s v, |v| = 1.
    return solveQuadratic(va * va - c2, 2.0 * (va * qa - c2 * glm::dot(ray.direction, q)),
                          qa * qa - c2 * glm::dot(q, q));
}

std::vector<Interval> spotLitIntervals(const Light& light, const Ray& ray) {
    const Interval whole{0.0, ray.length};
    if (light.type == Light::Directional ||
        (light.type == Light::Point && !std::isfinite(light.range)))
        return normalizeIntervals({&whole, 1}, ray.length);
    std::vector<double> cuts;
    if (light.type == Light::Spot)
        cuts = rayConeCrossings(ray, light.position, light.direction, light.outerAngle);
    if (std::isfinite(light.range)) {
        const std::vector<double> sphere = raySphereCrossings(ray, light.position, light.range);
        cuts.insert(cuts.end(), sphere.begin(), sphere.end());
    }
    // Between consecutive crossings the inside/outside answer is constant, so one test at each
    // piece's midpoint decides it, with the same predicate as irradiance().
    std::vector<Interval> lit;
    for (const Interval& piece : splitAt({&whole, 1}, cuts)) {
        const double mid = 0.5 * (piece.begin + piece.end);
        if (insideSpot(light, ray.origin + mid * ray.direction)) lit.push_back(piece);
    }
    return normalizeIntervals(lit, ray.length);
}

std::vector<double> lightFeatureDistances(const Light& light, const Ray& ray) {
    std::vector<double> points;
    if (light.type == Light::Directional) return points;
    const double closest = closestApproach(ray, light.position);
    const double h = lineDistance(ray, light.position);
    const double r0 = effectiveRadius(light);
    const double width = std::sqrt(h * h + r0 * r0);
    points.push_back(closest);
    appendGeometricMesh(points, closest, width, 1.0, 0.0, ray.length);
    appendGeometricMesh(points, closest, width, -1.0, 0.0, ray.length);
    if (light.type == Light::Spot) {
        // Both cones: the falloff's derivative jumps at the inner one.
        for (const double angle : {light.outerAngle, light.innerAngle}) {
            const std::vector<double> cone =
                rayConeCrossings(ray, light.position, light.direction, angle);
            points.insert(points.end(), cone.begin(), cone.end());
        }
    }
    if (std::isfinite(light.range)) {
        const std::vector<double> sphere = raySphereCrossings(ray, light.position, light.range);
        points.insert(points.end(), sphere.begin(), sphere.end());
    }
    return points;
}

void appendGeometricMesh(std::vector<double>& points, double origin, double first, double direction,
                         double lo, double hi) {
    if (!(first > 0.0) || !std::isfinite(first) || !std::isfinite(origin)) return;
    // The step grows geometrically, so the loop ends once it leaves (lo, hi), at worst when it
    // overflows to infinity (about 500 steps).
    for (double step = first;; step *= kMeshRatio) {
        const double x = origin + direction * step;
        if (direction > 0.0 ? !(x < hi) : !(x > lo)) break;
        if (x > lo && x < hi) points.push_back(x);
    }
}

std::vector<Interval> splitAt(std::span<const Interval> intervals, std::vector<double> points) {
    std::erase_if(points, [](double x) { return !std::isfinite(x); });  // NaN would break sort
    std::sort(points.begin(), points.end());
    std::vector<Interval> pieces;
    for (const Interval& in : intervals) {
        double start = in.begin;
        auto it = std::upper_bound(points.begin(), points.end(), in.begin);
        for (; it != points.end() && *it < in.end; ++it) {
            if (*it > start) {
                pieces.push_back({start, *it});
                start = *it;
            }
        }
        pieces.push_back({start, in.end});
    }
    return pieces;
}

}  // namespace ls::ref
