#version 450
#extension GL_GOOGLE_include_directive : require
// One light's in-scattering into the froxel grid: at one point of each froxel (its centre, or its
// own jittered point in the temporal mode) the light's irradiance with its shadow, cone, range
// and color (light_at.glsl) times the phase sum, per unit length (1/m, before the transmittance to
// the camera, which the integration applies). The frame's first light writes every froxel (0
// outside the columns it reaches); each later one adds within its own columns.
#include "froxel_grid.glsl"
#include "math.glsl"
#include "froxel_bindings.h"
#include "froxel_jitter.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
#if LS_SHADOW_MAP
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
layout(binding = LS_BINDING_SHADOW_MAP) uniform sampler2DArray shadowMap;  // six faces
#else
layout(binding = LS_BINDING_SHADOW_MAP) uniform sampler2D shadowMap;
#endif
#include "shadow.glsl"
#endif
#if LS_LIGHT_COLOR
layout(binding = LS_BINDING_LIGHT_COLOR) uniform sampler2D lightColorMap;
#endif
#include "light_color.glsl"
#include "light_at.glsl"
layout(binding = LS_BINDING_FROXEL_SCATTERING, rgba32f) uniform image3D scattering;

// The frame's first light: every froxel is written. Later lights: their columns only, added.
layout(constant_id = LS_SPEC_FROXEL_FIRST_LIGHT) const bool kFirstLight = true;

void main() {
    ivec3 g = ivec3(pc.grid.xyz);
    ivec3 f = ivec3(gl_GlobalInvocationID);
    if (!kFirstLight) f.xy += ivec2(pc.columns.xy);
    if (any(greaterThanEqual(f, g))) return;
    vec3 s = vec3(0.0);
    if (all(greaterThanEqual(vec2(f.xy), pc.columns.xy)) && all(lessThan(vec2(f.xy), pc.columns.zw))) {
        vec3 j = froxelJitter(f);
        vec3 v = rayDirection(columnNdc(vec2(f.xy), j.xy));
        float z = sliceZ(float(f.z) + j.z);
        vec3 P = frame.cameraPos.xyz + v * (z / axisCosine(v));
        float cosTheta;
        vec3 irr = lightAt(P, v, 0.0, cosTheta);
        s = phaseSum(cosTheta) * irr;
    }
    if (!kFirstLight) s += imageLoad(scattering, f).rgb;
    imageStore(scattering, f, vec4(s, 0.0));
}
