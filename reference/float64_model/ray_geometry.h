#pragma once

#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "interval.h"
#include "light.h"
#include "ray.h"

namespace ls::ref {

// The ray with a unit direction, or nothing when the direction is zero or not finite or the
// length is not finite: every Lin function answers such a ray with 0 instead of NaN. (Sky rays are
// clamped to maxDistance by the caller, so an infinite S is always a caller error.)
[[nodiscard]] std::optional<Ray> unitRay(const Ray& ray);

// Distance along the ray (from its origin, signed) of the point of its line closest to p.
[[nodiscard]] double closestApproach(const Ray& ray, const glm::dvec3& p);

// Distance from p to the ray's line, as |cross(v, C - p)|: sqrt(|q|^2 - b^2) would cancel
// catastrophically for a far point near the line.
[[nodiscard]] double lineDistance(const Ray& ray, const glm::dvec3& p);

// Distances along the ray's line (any sign, ascending) where it crosses the sphere.
[[nodiscard]] std::vector<double> raySphereCrossings(const Ray& ray, const glm::dvec3& centre,
                                                     double radius);

// Distances along the ray's line (any sign, ascending) where it crosses the double cone with the
// given apex, axis and half-angle. Crossings of the mirrored nappe are included: callers use these
// only as places where a piecewise function may change, and decide inside/outside separately.
[[nodiscard]] std::vector<double> rayConeCrossings(const Ray& ray, const glm::dvec3& apex,
                                                   const glm::dvec3& axis, double halfAngle);

// The parts of [0, ray.length] that a spot light's cone and range light (normalised), from the
// analytic crossings; [0, ray.length] for point and directional lights.
[[nodiscard]] std::vector<Interval> spotLitIntervals(const Light& light, const Ray& ray);

// Places where the integrand of a point or spot light changes character, for splitting
// quadrature pieces: the closest approach to the light and a geometric mesh around it (the
// Lorentzian 1/(s^2 + w^2) peak), and the spot's cone and range crossings.
[[nodiscard]] std::vector<double> lightFeatureDistances(const Light& light, const Ray& ray);

// Appends origin + direction * first * 4^k, k = 0, 1, ..., for the terms strictly inside (lo, hi).
// A geometric mesh resolves every length scale between first and hi - lo with a bounded number of
// points, which is what both the 1/r^2 peak and exp(-betaT s) need.
void appendGeometricMesh(std::vector<double>& points, double origin, double first, double direction,
                         double lo, double hi);

// Splits each interval at the points that fall strictly inside it.
[[nodiscard]] std::vector<Interval> splitAt(std::span<const Interval> intervals,
                                            std::vector<double> points);

}  // namespace ls::ref
