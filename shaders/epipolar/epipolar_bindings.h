// Epipolar sampling's own descriptor bindings (set 0, push descriptors), written once for both
// languages as shaders/shared/bindings.h's are: its shaders include it, passes/epipolar/ includes
// it as "shaders/epipolar/epipolar_bindings.h". Only #defines and comments. A shader's numbers
// here do not collide with the shared bindings the same shader also uses.
#ifndef LS_EPIPOLAR_BINDINGS_H
#define LS_EPIPOLAR_BINDINGS_H

// Every epipolar shader that reads its constants.
#define LS_BINDING_EPIPOLAR 5  // EpipolarConstants (epipolar_constants.glsl)

#define LS_BINDING_SLICE_END_POINTS_OUT 1  // slice_end_points.comp
// epipolar_coordinates.frag
#define LS_BINDING_COORDINATES_END_POINTS 1
#define LS_BINDING_COORDINATES_DEPTH 2
// slice_uv_frame.comp
#define LS_BINDING_UV_FRAME_END_POINTS 1
#define LS_BINDING_UV_FRAME_OUT 2
// min_max_trees.comp
#define LS_BINDING_TREE_SHADOW_MAP 1
#define LS_BINDING_TREE_UV_FRAME 2
#define LS_BINDING_TREE_OUT 3
// refine_samples.comp
#define LS_BINDING_REFINE_EPIPOLAR_Z 1
#define LS_BINDING_REFINE_SOURCES 2
#define LS_BINDING_REFINE_LIST 3  // the march list (marchesFromList), appended to
// refine_on_inscattering.frag
#define LS_BINDING_REFINE_MARCHED 1
#define LS_BINDING_REFINE_LIN_SOURCES 2
// mark_ray_march.frag, interpolate.frag (and the z of refine_on_inscattering.frag)
#define LS_BINDING_INTERPOLATION_SOURCE 1
#define LS_BINDING_INTERPOLATE_MARCHED 2
#define LS_BINDING_SOURCES_EPIPOLAR_Z 3  // which samples are valid (validSampleZ)
// ray_march.frag (and the shared march inputs: shadow map, point table, light color)
#define LS_BINDING_MARCH_COORDINATES 1
#define LS_BINDING_MARCH_EPIPOLAR_Z 2
#define LS_BINDING_MARCH_UV_FRAME 3
#define LS_BINDING_MARCH_TREES 4
#define LS_BINDING_MARCH_STEP_COUNTS 9
#define LS_BINDING_MARCH_END_POINTS 10  // a point light's cube only
#define LS_BINDING_MARCH_LIST 11  // the march list (mark_ray_march.frag, march_cover.vert too)
#define LS_BINDING_MARCH_OUT 12   // the marched samples, stored at their texels (marchTexel)
// unwarp.frag (and the shared point table and composite target)
#define LS_BINDING_UNWARP_END_POINTS 1
#define LS_BINDING_UNWARP_EPIPOLAR_Z 2
#define LS_BINDING_UNWARP_INSCATTER 3
#define LS_BINDING_UNWARP_DEPTH 4

#endif
