#pragma once
// Where seed 002's planes go this frame, computed on the CPU from the camera and the light: the
// view-space box of the light's volume (a spot's pyramid within its range, a shadowed directional
// light's box, otherwise the view frustum) cut to the camera's near plane and to the farthest a
// ray reaches, the number of planes and their spacing, and the per-frame values the shaders take
// as push constants (shaders/slices/slice_push.glsl).
#include <glm/glm.hpp>

#include <cstdint>

#include "shared/scattering_params.h"

namespace ls {

// Mirrors shaders/slices/slice_push.glsl (128 bytes, the push-constant size every device has).
struct SlicePush {
    glm::mat4 viewToWorld{1.0f};
    glm::vec4 boxMin{0.0f};  // xy, z: first plane's front depth, w: spacing
    glm::vec4 boxMax{0.0f};  // xy, z: plane count, w: 4 / range of the 8-bit target
    glm::vec4 noise{0.0f};   // scroll of the two layers, tiles
    glm::vec4 params{0.0f};  // ambient, noise amplitude, 1 / noise scale, farthest ray reach
};
static_assert(sizeof(SlicePush) == 128);

// Mirrors the push block of shaders/slices/slice_resolve.frag.
struct SliceResolvePush {
    glm::vec4 tint{0.0f};  // rgb: Lin per unit of the 8-bit channels' sum
    glm::vec4 slab{0.0f};  // x, y: the view depths the planes cover
};

struct SlicePlacement {
    SlicePush push;
    SliceResolvePush resolve;
    uint32_t planes = 0;  // 0: the light's volume misses the view, nothing to draw
};

SlicePlacement placeSlices(const CameraParams& camera, const LightParams& light,
                           const MediumParams& medium, const SliceSettings& settings, double time);

// The Lin luminance the four 8-bit channels hold at full scale when the engine gives none: 1.25
// times the largest luminance of the unshadowed Lin between view depths `front` and `back` (the
// planes' span) over 81 rays on a grid across the screen, each marched with 256 midpoint samples
// on the CPU. Unshadowed and to the end of the span, it bounds what those rays receive; a peak
// between them (beside a point light) can saturate, and where shadows darken most of the view the
// channels' steps are coarse: such scenes set Settings::sliceRange.
float estimatedSliceRange(const CameraParams& camera, const LightParams& light,
                          const MediumParams& medium, float front, float back);

}  // namespace ls
