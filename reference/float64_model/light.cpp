#include "light.h"

#include <algorithm>
#include <cmath>

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include "optical_depth.h"

namespace ls::ref {

double effectiveRadius(const Light& light) {
    return light.r0 > kMinLightRadius ? light.r0 : kMinLightRadius;  // NaN falls to the floor
}

bool insideSpot(const Light& light, const glm::dvec3& p) {
    if (light.type == Light::Directional) return true;
    const glm::dvec3 d = p - light.position;
    const double r = glm::length(d);
    if (!(r <= light.range)) return false;
    if (light.type != Light::Spot) return true;
    const double axisLength = glm::length(light.direction);
    // Written without dividing by r so that the apex itself counts as inside (0 >= 0).
    return glm::dot(d, light.direction) >= std::cos(light.outerAngle) * r * axisLength;
}

double falloff(const Light& light, const glm::dvec3& p) {
    if (light.type == Light::Directional) return 1.0;
    const glm::dvec3 d = p - light.position;
    const double r = glm::length(d);
    double f = 1.0;
    if (light.type == Light::Spot && light.innerAngle < light.outerAngle) {
        const double c = r > 0.0 ? glm::dot(d, glm::normalize(light.direction)) / r : 1.0;
        const double cosOuter = std::cos(light.outerAngle), cosInner = std::cos(light.innerAngle);
        const double a = std::clamp((c - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
        f = a * a;
    }
    if (light.windowedRange && std::isfinite(light.range)) {
        const double q = r / light.range;
        f *= std::clamp(1.0 - q * q * q * q, 0.0, 1.0);
    }
    return f;
}

glm::dvec3 irradiance(const Light& light, const Medium& medium, const glm::dvec3& p) {
    if (light.type == Light::Directional) return light.intensity;
    if (!insideSpot(light, p)) return glm::dvec3(0.0);
    const double r = glm::length(light.position - p);
    const double r0 = effectiveRadius(light);
    if (!medium.density.unit()) {
        const double tau = opticalDepth(medium.density, p, light.position);
        return light.intensity * glm::exp(-medium.betaT() * tau) / (r * r + r0 * r0) *
               falloff(light, p);
    }
    return light.intensity * glm::exp(-medium.betaT() * r) / (r * r + r0 * r0) * falloff(light, p);
}

double cosTheta(const Light& light, const glm::dvec3& v, const glm::dvec3& p) {
    const glm::dvec3 toLight =
        light.type == Light::Directional ? -light.direction : light.position - p;
    const double r = glm::length(toLight);
    if (r == 0.0) return 0.0;
    // Rounding can push the quotient a hair past 1; the phase functions are defined on [-1, 1].
    return std::clamp(glm::dot(v, toLight) / r, -1.0, 1.0);
}

}  // namespace ls::ref
