// The froxel grid (docs/methods.md, "froxels"): columns of grid.w x grid.w pixels, cut along the
// view axis into slices whose camera-space z grows geometrically from the near plane to the far
// distance, z(u) = near (far / near)^(u / slices) for u in [0, slices]. The push block is the
// passes' own; the frame constants are the light's (inject) or the first light's (camera and
// medium).
#ifndef LS_FROXEL_GRID_GLSL
#define LS_FROXEL_GRID_GLSL
#include "camera.glsl"

// The passes' push block; the temporal blend's (LS_FROXEL_TEMPORAL) has grid and slices too.
#define LS_VEC4 vec4
#define LS_MAT4 mat4
layout(push_constant) uniform FroxelPush {
#if defined(LS_FROXEL_TEMPORAL)
#include "froxel_temporal_push_fields.h"
#elif defined(LS_FROXEL_APPLY)
#include "froxel_apply_push_fields.h"
#else
#include "froxel_push_fields.h"
#endif
} pc;
#undef LS_VEC4
#undef LS_MAT4

// Camera-space z at slice coordinate u.
float sliceZ(float u) { return pc.slices.x * exp(pc.slices.z * u / pc.grid.z); }

// Slice coordinate of camera-space z, not clamped.
float sliceCoordinate(float z) { return log(max(z, 1e-30) / pc.slices.x) / pc.slices.z * pc.grid.z; }

// The whole grid's offset this frame, in froxels (the per-pixel history steps it; the grid's own
// temporal blend keeps the columns still).
#if defined(LS_FROXEL_TEMPORAL)
vec2 gridShift() { return vec2(0.0); }
#else
vec2 gridShift() { return pc.shift.xy; }
#endif

// The NDC of a point of a column, at (column + f) froxels from the grid's corner, f in [0, 1).
vec2 columnNdc(vec2 column, vec2 f) {
    return pixelToNdc((column + f + gridShift()) * pc.grid.w);
}

// dot(v, view axis) for a camera ray, floored as rayLength() floors it.
float axisCosine(vec3 v) { return max(dot(v, frame.cameraForward.xyz), 1e-4); }

#endif
