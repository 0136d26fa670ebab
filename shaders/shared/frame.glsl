// Per-frame constants (frame_constants_fields.h, std140) and the specialisation
// constants that select the light, the phase function and the options: the plugin compiles one
// pipeline per combination instead of branching per pixel.
#ifndef LS_FRAME_GLSL
#define LS_FRAME_GLSL
#include "bindings.h"

layout(constant_id = LS_SPEC_LIGHT_TYPE) const int kLightType = 0;       // 0 directional, 1 spot, 2 point
layout(constant_id = LS_SPEC_MIE_PHASE) const int kMiePhase = 0;        // 0 Cornette-Shanks, 1 isotropic, 2 hazy
layout(constant_id = LS_SPEC_LIGHT_COLOR) const bool kLightColor = false;  // colored shafts from a light-space texture
layout(constant_id = LS_SPEC_BILINEAR_SHADOW) const bool kBilinearShadow = true;
// Seed 004's simplified light model (Settings::lightModel, eqs. 2.12-2.17): irradiance
// I / (a1 r^2 + a0), no transmittance, isotropic phase; the shaders that honour it read
// frame.simplified (simplified.glsl, light_at.glsl).
layout(constant_id = LS_SPEC_SIMPLIFIED_MODEL) const bool kSimplifiedModel = false;
// A non-uniform medium's parts (LS_MEDIA_* bits; medium.glsl): 0 compiles today's homogeneous
// shaders, whose every density is 1.
layout(constant_id = LS_SPEC_MEDIA) const int kMedia = 0;

const int LIGHT_DIRECTIONAL = LIGHTSCATTER_LIGHT_DIRECTIONAL;
const int LIGHT_SPOT = LIGHTSCATTER_LIGHT_SPOT;
const int LIGHT_POINT = LIGHTSCATTER_LIGHT_POINT;
const float PI = 3.14159265358979;

layout(std140, set = 0, binding = LS_BINDING_FRAME) uniform FrameConstants {
#define LS_MAT4 mat4
#define LS_VEC4 vec4
#define LS_DEFAULT(x, y, z, w)
#include "frame_constants_fields.h"
#undef LS_MAT4
#undef LS_VEC4
#undef LS_DEFAULT
} frame;

// Lin as a method leaves it for the composite and as the composite reads it back: scaled by the
// frame's power of two (plugin_api/lin_storage.h), which keeps the frame's brightest Lin within
// float16's range, and clamped to that range (a sampled method's peak may overshoot the bound).
// Exact: a power of two changes no float16 digit.
vec3 storedLin(vec3 lin) { return clamp(lin * frame.linStorage.x, vec3(-65504.0), vec3(65504.0)); }
vec3 loadedLin(vec3 stored) { return stored * frame.linStorage.y; }

#endif
