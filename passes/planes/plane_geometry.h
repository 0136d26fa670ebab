#pragma once
// Where seed 002's planes go this frame, computed on the CPU from the camera and the light: the
// view-space box of the light's volume (a spot's pyramid within its range, a shadowed directional
// light's box, otherwise the view frustum) cut to the camera's near plane and to the farthest a
// ray reaches, the number of planes and their spacing, and the per-frame values the shaders take
// as push constants (shaders/planes/plane_push.glsl).
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "lightscatter/settings.h"
#include "plane_settings.h"
#include "shared/scattering_params.h"

namespace ls {

// The push blocks of shaders/planes/plane_push.glsl and plane_resolve.frag, their fields written
// once (shaders/planes/*_push_fields.h). Only mat4 and vec4 members: laid out as the blocks are.
#define LS_MAT4 glm::mat4
#define LS_VEC4 glm::vec4
#define LS_INIT(x) \
    { x }
struct PlanePush {
#include "shaders/planes/plane_push_fields.h"
};
struct PlaneResolvePush {
#include "shaders/planes/plane_resolve_push_fields.h"
};
#undef LS_MAT4
#undef LS_VEC4
#undef LS_INIT
static_assert(sizeof(PlanePush) == 128);  // the push-constant size every device has
static_assert(sizeof(PlaneResolvePush) == 32);

struct PlanePlacement {
    PlanePush push;
    PlaneResolvePush resolve;
    uint32_t planes = 0;  // 0: the light's volume misses the view, nothing to draw
};

// The placement's settings: Settings::planes' and the noise's.
PlaneSettings planeSettings(const lightscatter::Settings& s);

PlanePlacement placePlanes(const CameraParams& camera, const LightParams& light,
                           const MediumParams& medium, const PlaneSettings& settings, double time);

// The convex polygon (counter-clockwise, view-space x and y on the plane at view depth `depth`)
// through which every view ray passes that crosses a spot light's pyramid between view depths
// `front` and `back` (`front` 0: from the camera on), cut to the view; empty where no ray does. A
// plane cut to the cone at its own depth misses the rays that cross the cone between two planes
// (beside its apex, where the cone is narrower than a slab is long): a slab drawn over this
// polygon does not.
std::vector<glm::vec2> spotSlabFootprint(const CameraParams& camera, const LightParams& light,
                                         const MediumParams& medium, float front, float back,
                                         float depth);

// The frame report's note on a placement: "N sampling planes S m apart".
std::string planesNote(uint32_t planes, float spacing);

// The Lin luminance the four 8-bit channels hold at full scale when the engine gives none: 1.25
// times the largest luminance of the unshadowed Lin between view depths `front` and `back` (the
// planes' span) over 81 rays on a grid across the screen, each marched with 256 midpoint samples
// on the CPU. Unshadowed and to the end of the span, it bounds what those rays receive; a peak
// between them (beside a point light) can saturate, and where shadows darken most of the view the
// channels' steps are coarse: such scenes set Settings::planes.range.
float estimatedPlaneRange(const CameraParams& camera, const LightParams& light,
                          const MediumParams& medium, float front, float back);

}  // namespace ls
