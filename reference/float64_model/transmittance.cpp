#include "transmittance.h"

#include <algorithm>
#include <optional>

#include <glm/exponential.hpp>

#include "optical_depth.h"
#include "ray_geometry.h"

namespace ls::ref {

glm::dvec3 transmittance(const Medium& medium, const Ray& ray, double s) {
    if (medium.density.unit()) return glm::exp(-medium.betaT() * std::max(s, 0.0));
    return glm::exp(-medium.betaT() * opticalDepth(medium.density, ray, 0.0, s));
}

glm::dvec3 viewTransmittance(const Medium& medium, const Ray& ray) {
    const std::optional<Ray> unit = unitRay(ray);
    if (!unit) return glm::dvec3(1.0);
    return transmittance(medium, *unit, unit->length);
}

}  // namespace ls::ref
