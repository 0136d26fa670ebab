// The interface between the scattering passes and their shaders, written once: descriptor binding
// numbers and specialisation-constant ids. Compiled by both languages: the shaders include it
// (GL_GOOGLE_include_directive) and name these in layout(binding = ...) and
// layout(constant_id = ...); the passes include it as "shaders/shared/bindings.h" and name the
// same macros in their binding tables and specialisation data. Only #defines and comments, so both
// preprocessors read it alike.
// Only what more than one method or the shared shaders use is here. A method's own are in its
// shader folder (shaders/<method>/<method>_bindings.h), written the same way: its binding numbers
// do not collide with the shared ones the same shader also uses, and its specialisation-constant
// ids start at 10, past frame.glsl's (ids may repeat across shaders that never share a pipeline).
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
#define LS_BINDING_COMPOSITE_T 13   // composite_into.glsl (LS_SPLIT): the transmittance image
// Bindings of one shader each.
#define LS_BINDING_POINT_TABLE_OUT 1  // point_table.comp
#define LS_BINDING_COMPOSITE_LIN 3    // composite.comp: Lin as a method left it
#define LS_BINDING_NOISE_OUT 0        // tiling_noise.comp
// composite_blend.frag, composite_apply.comp and transmittance_export.comp: the split composite's
// images (composite_into.glsl's LS_SPLIT), and the engine's color or transmittance output.
#define LS_BINDING_SPLIT_LIN 1
#define LS_BINDING_SPLIT_T 2
#define LS_BINDING_SPLIT_TARGET 3

// The light types' and Mie phases' values (LIGHTSCATTER_LIGHT_*, LIGHTSCATTER_MIE_*) are the
// vocabulary's, which C++ names lightscatter::LightType and lightscatter::MiePhase.
#include "lightscatter/vocabulary.h"

// Specialisation constants of frame.glsl (ScatterSpec::constants()).
#define LS_SPEC_LIGHT_TYPE 0  // 0 directional, 1 spot, 2 point
#define LS_SPEC_MIE_PHASE 1   // 0 Cornette-Shanks, 1 isotropic, 2 hazy
#define LS_SPEC_MEDIA 2       // LS_MEDIA_* bits: 0, a homogeneous medium
#define LS_SPEC_LIGHT_COLOR 3
#define LS_SPEC_BILINEAR_SHADOW 4
#define LS_SPEC_SIMPLIFIED_MODEL 5

// A non-uniform medium's parts (ScatterSpec::media), and the fog volumes the frame constants hold
// (lightscatter::limits::kMaxFogVolumes).
#define LS_MEDIA_HEIGHT_FOG 1
#define LS_MEDIA_VOLUMES 2
#define LS_MEDIA_FADES 4  // a volume with a soft edge (fade > 0)
#define LS_MAX_FOG_VOLUMES 64

#endif
