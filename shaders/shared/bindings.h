// The interface between the scattering passes and their shaders, written once: descriptor binding
// numbers and specialisation-constant ids. Compiled by both languages: the shaders include it
// (GL_GOOGLE_include_directive) and name these in layout(binding = ...) and
// layout(constant_id = ...); the passes include it as "shaders/shared/bindings.h" and name the
// same macros in their binding tables and specialisation data. Only #defines and comments, so both
// preprocessors read it alike.
#ifndef LS_BINDINGS_H
#define LS_BINDINGS_H

// Bindings every scattering shader that reads them uses (set 0, push descriptors).
#define LS_BINDING_FRAME 0          // FrameConstants (frame.glsl)
#define LS_BINDING_DEPTH 1          // the engine's depth (passes other than the epipolar ones)
#define LS_BINDING_SHADOW_MAP 6     // the light's shadow map (a 2D array for a point light's cube)
#define LS_BINDING_POINT_TABLE 7    // the point-light table (point_table.comp)
#define LS_BINDING_LIGHT_COLOR 8    // the light-space color texture
#define LS_BINDING_NOISE 9          // the planes' tiling noise (repeating)
#define LS_BINDING_ENGINE_COLOR 10  // composite_into.glsl: the engine's color, read-modify-written
#define LS_BINDING_LIN_OUT 11       // composite_into.glsl: the Lin output image
// Bindings every epipolar shader that reads them uses (shaders/epipolar/).
#define LS_BINDING_EPIPOLAR 5  // EpipolarConstants (epipolar_constants.glsl)

// Bindings of one shader each.
#define LS_BINDING_POINT_TABLE_OUT 1       // point_table.comp
#define LS_BINDING_COMPOSITE_LIN 3         // composite.comp: Lin as a method left it
#define LS_BINDING_NOISE_OUT 0             // tiling_noise.comp
#define LS_BINDING_PLANE_SUM 2             // plane_resolve.frag
#define LS_BINDING_BEAM_TRIANGLES 3        // triangles.vert
#define LS_BINDING_SLICE_END_POINTS_OUT 1  // slice_end_points.comp
// epipolar_coordinates.frag
#define LS_BINDING_COORDINATES_END_POINTS 1
#define LS_BINDING_COORDINATES_DEPTH 2
// slice_uv_frame.comp
#define LS_BINDING_UV_FRAME_END_POINTS 1
#define LS_BINDING_UV_FRAME_OUT 2
// min_max_first_level.comp, min_max_next_level.comp
#define LS_BINDING_TREE_SHADOW_MAP 1
#define LS_BINDING_TREE_UV_FRAME 2
#define LS_BINDING_TREE_FIRST_LEVEL 3
#define LS_BINDING_TREE_LEVEL 0
// refine_samples.comp
#define LS_BINDING_REFINE_EPIPOLAR_Z 1
#define LS_BINDING_REFINE_SOURCES 2
// refine_on_inscattering.frag
#define LS_BINDING_REFINE_MARCHED 1
#define LS_BINDING_REFINE_LIN_SOURCES 2
// mark_ray_march.frag, interpolate.frag
#define LS_BINDING_INTERPOLATION_SOURCE 0
#define LS_BINDING_INTERPOLATE_MARCHED 1
// ray_march.frag (and the march inputs above)
#define LS_BINDING_MARCH_COORDINATES 1
#define LS_BINDING_MARCH_EPIPOLAR_Z 2
#define LS_BINDING_MARCH_UV_FRAME 3
#define LS_BINDING_MARCH_TREES 4
#define LS_BINDING_MARCH_STEP_COUNTS 9
// unwarp.frag (and the point table, the composite target above)
#define LS_BINDING_UNWARP_END_POINTS 1
#define LS_BINDING_UNWARP_EPIPOLAR_Z 2
#define LS_BINDING_UNWARP_INSCATTER 3
#define LS_BINDING_UNWARP_DEPTH 4
// froxels (shaders/froxels/)
#define LS_BINDING_FROXEL_SCATTERING 2   // inject.comp, integrate.comp: in-scattering per froxel
#define LS_BINDING_FROXEL_INTEGRATED 3   // integrate.comp, apply.comp: Lin and T to each froxel
#define LS_BINDING_FROXEL_HISTORY 4      // temporal.comp: the frame before's in-scattering grid
#define LS_BINDING_FROXEL_HISTORY_OUT 5  // temporal.comp: this frame's, for the next
#define LS_BINDING_FROXEL_VOLUME_OUT 12  // export.comp: the engine's 3D image (volumeOut)

// The light types' and Mie phases' values (LIGHTSCATTER_LIGHT_*, LIGHTSCATTER_MIE_*) are the
// vocabulary's, which C++ names lightscatter::LightType and lightscatter::MiePhase.
#include "lightscatter/vocabulary.h"

// Specialisation constants of frame.glsl (ScatterSpec::constants()); id 2 is unused.
#define LS_SPEC_LIGHT_TYPE 0  // 0 directional, 1 spot, 2 point
#define LS_SPEC_MIE_PHASE 1   // 0 Cornette-Shanks, 1 isotropic, 2 hazy
#define LS_SPEC_LIGHT_COLOR 3
#define LS_SPEC_BILINEAR_SHADOW 4
#define LS_SPEC_SIMPLIFIED_MODEL 5
// One shader's own, from 10 up (ids may repeat across shaders that never share a pipeline).
#define LS_SPEC_CONE_SAMPLES 10  // cone_march.frag
#define LS_SPEC_CONE_LIMITED 11
#define LS_SPEC_CONE_JITTER 12
#define LS_SPEC_PLANES_CHANNELS 10  // planes.frag
#define LS_SPEC_PLANES_DITHER 11
#define LS_SPEC_RESOLVE_CHANNELS 10  // plane_resolve.frag
#define LS_SPEC_RESOLVE_BLUR_RADIUS 11
#define LS_SPEC_RESOLVE_CLOSED_FORM_OUTSIDE_SLAB 12
#define LS_SPEC_UNCLIPPED_DEPTH 20     // triangles.vert
#define LS_SPEC_FROXEL_FIRST_LIGHT 10  // inject.comp

#endif
