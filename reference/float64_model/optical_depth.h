#pragma once

#include <glm/vec3.hpp>

#include "density.h"
#include "ray.h"

namespace ls::ref {

// G(x) = (1 - exp(-x)) / x, the mean of exp(-u) over u in [0, x], for x >= 0: -expm1(-x) / x,
// with G(0) = 1 (and G(inf) = 0).
[[nodiscard]] double meanDecay(double x);

// The integral of h(y) (docs/model.md's height fog, without d0) over t in [t0, t1] of the line
// origin + t direction, direction unit: split where it crosses y = h0, the length below it, and
// above it exp(-k (y_low - h0)) l G(k |dy| l). Finite for every k >= 0, dy = 0 included.
[[nodiscard]] double heightOpticalDepth(const HeightFog& fog, const glm::dvec3& origin,
                                        const glm::dvec3& direction, double t0, double t1);

// The integral of the box's weight b(x) (without its density) over t in [t0, t1] of the line
// origin + t direction, direction unit: its chord for a hard box, and for a faded one Simpson's
// rule on each piece between boxWeightKinks, exact there because the weight is a cubic in t.
[[nodiscard]] double boxOpticalDepth(const FogBox& box, const glm::dvec3& origin,
                                     const glm::dvec3& direction, double t0, double t1);

// The integral of m over s in [s0, s1] of a ray with a unit direction (0 when s1 <= s0): the
// camera ray's tau(s1) - tau(s0), computed directly, never as a difference.
[[nodiscard]] double opticalDepth(const Density& density, const Ray& ray, double s0, double s1);

// The integral of m along the straight segment from a to b.
[[nodiscard]] double opticalDepth(const Density& density, const glm::dvec3& a, const glm::dvec3& b);

}  // namespace ls::ref
