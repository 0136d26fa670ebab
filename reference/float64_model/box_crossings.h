#pragma once

#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "density.h"
#include "interval.h"

namespace ls::ref {

// Where the line origin + t direction lies in the closed box: the t range between its entry and
// exit faces (a single point when it grazes an edge), or nothing when it misses. A direction
// parallel to a pair of faces keeps the whole line between them or none of it.
[[nodiscard]] std::optional<Interval> boxSpan(const FogBox& box, const glm::dvec3& origin,
                                              const glm::dvec3& direction);

// The t where the box's weight along the line is not a polynomial, sorted: the span's ends (the
// faces), and, for a faded box, the fade planes |local_j| = a_j - f where a_j > f and the centre
// plane local_j = 0 where a_j <= f (there |local_j| kinks before the factor saturates). Between
// consecutive ones every factor is linear in t, so the weight is a cubic. Empty when the line
// misses the box.
[[nodiscard]] std::vector<double> boxWeightKinks(const FogBox& box, const glm::dvec3& origin,
                                                 const glm::dvec3& direction);

}  // namespace ls::ref
