#pragma once

#include <limits>

#include <glm/vec3.hpp>

#include "medium.h"

namespace ls::ref {

struct Light {
    // Unscoped so that both Light::Spot and Light::Type::Spot read naturally.
    enum Type { Directional, Spot, Point };

    Type type = Point;
    glm::dvec3 position{0.0};  // ignored by directional lights
    // Directional: the direction the light travels. Spot: the cone axis, away from the apex.
    glm::dvec3 direction{0.0, -1.0, 0.0};
    // Directional: irradiance E (W/m^2). Point and spot: radiant intensity I (W/sr).
    glm::dvec3 intensity{1.0};
    // Spot: the outer cone's half-angle, where the light ends, and the inner one's, where its
    // KHR_lights_punctual falloff begins (radians; equal: a hard edge).
    double outerAngle = 0.5;
    double innerAngle = 0.5;
    double range = std::numeric_limits<double>::infinity();  // point and spot: none beyond it
    bool windowedRange = false;  // the range ends in KHR's window (1 - (d/range)^4)
    double r0 = 0.05;            // light radius, metres
};

// r0 is floored here so that r0 = 0 (seed 000's singular formula) still keeps a ray through the
// light finite, as docs/model.md requires; 1 micrometre changes nothing at the scale of a scene.
inline constexpr double kMinLightRadius = 1.0e-6;
[[nodiscard]] double effectiveRadius(const Light& light);

// Irradiance reaching the point p, before visibility (W/m^2 per channel). Point and spot lights
// attenuate by exp(-betaT tau) / (r^2 + r0^2) times falloff(), tau the optical depth of the
// medium's density from p to the light (r when m = 1); spot lights are zero outside the
// single outer cone (dot(p - L, axis) >= cos(outer) |p - L|, boundary included, apex included),
// point and spot lights beyond range.
[[nodiscard]] glm::dvec3 irradiance(const Light& light, const Medium& medium, const glm::dvec3& p);

// Cosine of the scattering angle at p for a viewer looking along the unit v: dot(v, normalize(L -
// p)) for point and spot lights, dot(v, -direction) for directional ones. At p == L the direction
// to the light is undefined; 0 is returned, the mean of the two one-sided limits +1 and -1 of a ray
// through the light (a single point, so it never changes an integral).
[[nodiscard]] double cosTheta(const Light& light, const glm::dvec3& v, const glm::dvec3& p);

// Whether p is inside the light's volume: a spot's outer cone and its range, a point light's range
// (true for directional lights).
[[nodiscard]] bool insideSpot(const Light& light, const glm::dvec3& p);

// The smooth edges' factor inside that volume (docs/model.md, "The lights"): a spot's angular
// falloff clamp((cos t - cos outer) / (cos inner - cos outer), 0, 1)^2, 1 within the inner cone
// and for a hard edge; times the range window clamp(1 - (d / range)^4, 0, 1) when windowed.
[[nodiscard]] double falloff(const Light& light, const glm::dvec3& p);

}  // namespace ls::ref
