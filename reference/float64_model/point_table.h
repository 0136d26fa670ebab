#pragma once

#include <span>

#include <glm/vec3.hpp>

#include "gauss_kronrod.h"
#include "interval.h"
#include "light.h"
#include "medium.h"
#include "ray.h"

namespace ls::ref {

// A ray in the table's coordinates. s is measured along the ray's direction from L0, the light's
// projection onto the ray's line, so the point at camera distance d has s = sCamera + d.
struct PointRayFrame {
    double h = 0.0;        // distance from the light to the ray's line, |cross(v, C - L)|
    double sCamera = 0.0;  // s of the camera: dot(v, C - L), negative when L0 lies ahead of it
};
[[nodiscard]] PointRayFrame pointRayFrame(const Light& light, const Ray& ray);

// docs/model.md's table entry (the light's intensity included):
//   T[h, s] = I * integral over x in [s, inf) of
//             P(t(x)) exp(-betaT (x - s)) exp(-betaT sqrt(h^2 + x^2)) / (h^2 + x^2 + r0^2) dx,
// with cos t(x) = -x / sqrt(h^2 + x^2) (0 at h = x = 0, as cosTheta() does at the light).
// Integrated to options.relTol on a growing range [s, X]; X grows by 16x until the bound
// I max(P) exp(-betaT (2X - s)) / X on what lies beyond is below 1e-16 of the sum in every channel.
// No range or cone cut: for a spot light the caller restricts the lit intervals instead.
// The table assumes m = 1 everywhere: std::invalid_argument for a medium whose density varies or is
// not 1 (fold a homogeneous density into the coefficients first).
[[nodiscard]] glm::dvec3 pointTable(const Medium& medium, const Light& light, double h, double s,
                                    const QuadOptions& options = {});

// One lit segment [sa, sb] (table coordinates, sa <= sb, both >= sCamera):
//   exp(-betaT (sa - sCamera)) T[h, sa] - exp(-betaT (sb - sCamera)) T[h, sb],
// i.e. light scattered towards the camera from the segment, attenuated on its way to the camera.
// The difference cancels when the segment holds little of T[h, sa]: its absolute error is about
// relTol * T[h, sa], not relTol times the result.
[[nodiscard]] glm::dvec3 pointTableSegment(const Medium& medium, const Light& light, double h,
                                           double sCamera, double sa, double sb,
                                           const QuadOptions& options = {});

// Lin of a point or spot light from the table: the sum of pointTableSegment over the lit intervals
// (camera distances, clipped to [0, S]), intersected with the spot's cone and range for a spot.
// Throws std::invalid_argument for a directional light, and as pointTable does.
[[nodiscard]] glm::dvec3 inscatterFromPointTable(const Medium& medium, const Light& light,
                                                 const Ray& ray, std::span<const Interval> lit,
                                                 const QuadOptions& options = {});
[[nodiscard]] glm::dvec3 inscatterFromPointTable(const Medium& medium, const Light& light,
                                                 const Ray& ray, const QuadOptions& options = {});

}  // namespace ls::ref
