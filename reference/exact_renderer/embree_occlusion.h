#pragma once
// Occlusion queries of the reference renderer through Intel Embree's BVH, exact in float64.
//
// Embree only finds candidates: each triangle is an Embree user primitive whose float box is the
// triangle's box widened by kPadding times the scene's coordinate scale, far more than the float
// rounding of the ray and of Embree's own box tests, so no triangle the double test would hit is
// culled. Every candidate is tested by intersectTriangle in double. A query therefore answers
// exactly what Bvh::anyHitOwn answers, bit for bit; only the traversal is Embree's (its 4- and
// 8-wide SIMD box tests instead of the double BVH's scalar slabs, which took ~65% of the reference
// renderer's time).
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "bvh.h"

namespace host::reference {

class EmbreeOcclusion {
  public:
    // The box widening, as a fraction of the scene's coordinate scale.
    static constexpr double kPadding = 1.0 / 16384.0;
    // Rays whose origin lies further than this many coordinate scales from 0 are left to the
    // double BVH: there the float rounding of the origin would approach the padding.
    static constexpr double kReach = 32.0;

    virtual ~EmbreeOcclusion() = default;
    // Whether any triangle is hit with t in [tMin, tMax] (Bvh::anyHit's contract), or nothing
    // when this ray is one the padding does not cover (see kReach).
    [[nodiscard]] virtual std::optional<bool> anyHit(const PreparedRay& ray, double tMin,
                                                     double tMax) const = 0;
    // The same for many queries at once, traced as packets: hits[i] becomes 1 or 0 for every
    // query this object answers and is left at kUnanswered for the others.
    static constexpr uint8_t kUnanswered = 2;
    virtual void anyHit(std::span<const OcclusionQuery> queries, std::span<uint8_t> hits) const = 0;
};

// Embree's scene over `triangles` (copied), or nullptr where the build has no Embree or the CPU
// is one Embree refuses. `coordinateScale` is Bvh::coordinateScale().
[[nodiscard]] std::shared_ptr<const EmbreeOcclusion> makeEmbreeOcclusion(
    const std::vector<Triangle>& triangles, double coordinateScale);

}  // namespace host::reference
