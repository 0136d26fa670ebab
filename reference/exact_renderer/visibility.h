#pragma once
// docs/model.md's V: exact visibility of the light from a point of the medium, traced against the
// scene's triangles, and the lit intervals of a view ray found from it.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "bvh.h"
#include "float64_model/interval.h"
#include "float64_model/light.h"
#include "float64_model/ray.h"

namespace host::reference {

// Shadow rays ignore hits closer than this fraction of the scene's coordinate scale to their
// start (and, for point and spot lights, to the light): a few times the rounding of a hit
// distance (a few ulps of the coordinates), so that a shadow ray starting on a surface does not
// hit that surface. It must stay far below the end offset of litIntervals (relTol S along the view
// ray): a huge ground quad sets the coordinate scale, and a larger offset would let the medium just
// in front of a back-lit surface see through it.
inline constexpr double kShadowOffset = 16.0 * 2.220446049250313e-16;

class LightVisibility {
  public:
    LightVisibility(const Bvh& bvh, const ls::ref::Light& light);

    // Whether the segment from p to the light (point, spot: to its position; directional: along
    // -direction to infinity) misses every triangle. A triangle through p itself does not count
    // (see kShadowOffset), nor one through the light's position.
    [[nodiscard]] bool visible(const glm::dvec3& p) const;
    // visible() of each point (out[i] for points[i], 1 or 0), asked of the BVH together.
    void visible(std::span<const glm::dvec3> points, std::span<uint8_t> out) const;

  private:
    // The shadow ray from p, or nothing when p is at the light (nothing can lie in between).
    [[nodiscard]] std::optional<OcclusionQuery> shadowRay(const glm::dvec3& p) const;

    const Bvh* bvh_;
    ls::ref::Light light_;
    glm::dvec3 towardLight_{0.0};  // directional only: unit -direction
    double offset_ = 0.0;
};

struct LitSearch {
    int samples = 512;     // uniform over [0, S]
    double relTol = 1e-9;  // shadow boundaries are bisected to relTol * S
    bool shadows = true;   // false: the light's own volume only (V = 1)
};

// The lit intervals of a view ray (unit direction, length S): the light's volume (the spot's cone
// and range from ls::ref::spotLitIntervals, the whole ray otherwise) intersected with V = 1.
// V is sampled on the grid k S / samples and at the volume's boundaries; every change of V
// between neighbouring samples is bisected to relTol * S and placed at the final bracket's
// middle. A shadow (or a gap of light) shorter than the grid spacing that falls between two
// samples is missed: that is the sampling's only approximation.
// The ray's end lies on a surface (or is the sky's end), so V at s in (S - relTol S, S] is taken
// as V at S - relTol S, the medium just in front of it: a back-lit surface shadows the medium up to
// itself, and a lit surface does not shadow its own point.
[[nodiscard]] std::vector<ls::ref::Interval> litIntervals(const LightVisibility& visibility,
                                                          const ls::ref::Light& light,
                                                          const ls::ref::Ray& ray,
                                                          const LitSearch& search = {});

}  // namespace host::reference
