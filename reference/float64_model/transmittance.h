#pragma once

#include <glm/vec3.hpp>

#include "medium.h"
#include "ray.h"

namespace ls::ref {

// docs/model.md's camera-ray transmittance T(s) = exp(-betaT tau(s)) per channel, tau(s) the
// integral of m over [0, s] of a ray with a unit direction; exp(-betaT s) when m = 1.
[[nodiscard]] glm::dvec3 transmittance(const Medium& medium, const Ray& ray, double s);

// T(S) of a ray with any non-zero direction: what the composite Lobj T(S) + Lin multiplies the
// surface's radiance by. A zero or non-finite direction, or an S that is not finite, gives 1
// (nothing lies in front), as such a ray's Lin is 0.
[[nodiscard]] glm::dvec3 viewTransmittance(const Medium& medium, const Ray& ray);

}  // namespace ls::ref
