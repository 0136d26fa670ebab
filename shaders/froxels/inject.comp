#version 450
#extension GL_GOOGLE_include_directive : require
// One light's in-scattering into the froxel grid: at one point of each froxel (its centre, or its
// own jittered point in the temporal mode) the light's irradiance with its shadow, cone, range
// and color (light_at.glsl) times the phase sum, per unit length (1/m, before the transmittance to
// the camera, which the integration applies). The frame's first light writes every froxel (0
// outside the columns it reaches); each later one adds within its own columns.
// LS_SLAB (a point or spot light, its point-light table bound): a point sample is meaningless near
// the light, where the inverse square peaks inside one froxel (a spot on screen was 96-292% off):
// the froxel's slice of its column's ray, cut to the light's volume, takes the closed form of the
// unshadowed Lin over it (integrate.glsl), divided by the weight the integration gives the froxel,
// times the shadow and color at the lit part's middle. A non-uniform medium and seed 004's
// simplified model keep the point sample. The temporal mode keeps the column's centre ray (jittered
// across the column, the history blurred the shafts between centres: 0.53 off against 0.45 on
// window_room at 16-pixel columns) and moves only the shadow's point along each slice.
#ifndef LS_SLAB
#define LS_SLAB 0
#endif
#include "froxel_grid.glsl"
#include "math.glsl"
#include "froxel_bindings.h"
#include "froxel_jitter.glsl"
#if LS_SLAB
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;  // one invocation per column
#else
layout(local_size_x = 32, local_size_y = 4, local_size_z = 1) in;  // one per froxel, 32 x 4
#endif
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
#if LS_SLAB
#define LS_NEEDS_TABLE 1
layout(binding = LS_BINDING_POINT_TABLE) uniform sampler2D pointTable;
#include "integrate.glsl"
#include "light_volume.glsl"
#endif
layout(binding = LS_BINDING_FROXEL_SCATTERING, rgba32f) uniform image3D scattering;

// The frame's first light: every froxel is written. Later lights: their columns only, added.
layout(constant_id = LS_SPEC_FROXEL_FIRST_LIGHT) const bool kFirstLight = true;

float channelMean(vec3 c) { return dot(c, vec3(1.0 / 3.0)); }

// Whether the light's screen rectangle reaches the column.
bool reachesColumn(ivec2 column) {
    return all(greaterThanEqual(vec2(column), pc.columns.xy)) && all(lessThan(vec2(column), pc.columns.zw));
}

// Alpha: the mean over channels of the froxel's in-scattering without shadow or cookie, summed over
// the frame's lights, which the temporal blend uses to carry its history across a light's motion
// (temporal.comp); -1 once a light whose unshadowed value is itself a jittered point sample (one
// without its slab) adds to the froxel, where the blend keeps its history as it is.
void store(ivec3 f, vec3 s, float unshadowed) {
    if (!kFirstLight) {
        vec4 before = imageLoad(scattering, f);
        s += before.rgb;
        unshadowed = before.a < 0.0 || unshadowed < 0.0 ? -1.0 : before.a + unshadowed;
    }
    imageStore(scattering, f, vec4(s, unshadowed));
}

#if LS_SLAB
// What integrate.comp, weighing the slice [s0, s1] of the ray by its transmittance to s0 and its
// attenuated length, turns into `lin`, the slice's Lin.
vec3 perUnitLength(vec3 lin, float s0, float s1) {
    vec3 betaT = frame.betaT.rgb;
    return lin / max(exp(-betaT * s0) * attenuatedLength(betaT, s1 - s0), vec3(1e-30));
}

// The slice [s0, s1] of the ray from C along v on its own: its closed-form unshadowed Lin cut to the
// light's volume, times the shadow and color at the lit part's middle, per unit length.
vec3 slabScattering(vec3 C, vec3 v, float s0, float s1) {
    float t0, t1;
    lightInterval(C, v, s1, t0, t1);
    t0 = max(t0, s0);
    if (!(t0 < t1)) return vec3(0.0);
    vec3 V = vec3(1.0);
    applyShadowAndColor(C + (0.5 * (t0 + t1)) * v, V);
    return perUnitLength(V * unshadowedInscatter(C, v, t0, t1), s0, s1);
}

// A point or spot light's column: each slice of the centre ray (the column's centre pixel: exact
// there, and what the apply pass interpolates between centres) takes the closed form of the
// unshadowed Lin over its part in the light's volume, times the shadow and color at that part's
// middle. One invocation marches the column front to back, so each slice boundary's closed form is
// evaluated once and the light's volume is met once per ray: the cost of the point samples it
// replaces. The host picks this variant only for a point or spot light in a homogeneous medium
// under the full model (FroxelsMethod::readsTable); the others keep the point samples.
void main() {
    ivec3 g = ivec3(pc.grid.xyz);
    ivec2 column = ivec2(gl_GlobalInvocationID.xy);
    if (!kFirstLight) column += ivec2(pc.columns.xy);
    if (any(greaterThanEqual(column, g.xy))) return;
    if (!reachesColumn(column)) {
        for (int z = 0; z < g.z; ++z) store(ivec3(column, z), vec3(0.0), 0.0);
        return;
    }
    vec3 C = frame.cameraPos.xyz;
    vec3 v = rayDirection(columnNdc(vec2(column), vec2(0.5)));
    float perZ = 1.0 / axisCosine(v);
    float t0, t1;
    lightInterval(C, v, sliceZ(float(g.z)) * perZ, t0, t1);
    Inscatter a = beginInscatter(C, v, max(t0, 0.0));
    // A ray's integral grows as 1 / h, h its distance to the light, so in the slice that holds the
    // light a centre ray passing close to it, or through a spot's apex seen from the side, spreads
    // over the froxel a glow few of its pixels have (a far spot at 64x36 took 2.2 times its
    // energy). There the value is bounded, as engines bound a punctual light near its froxel, by
    // twice the mean of four rays a quarter of the column in from its corners: the froxel's energy.
    vec3 D = frame.lightPos.xyz - C;
    float along = dot(D, v);
    vec3 edge = rayDirection(columnNdc(vec2(column), vec2(1.0, 0.5)));
    bool besideLight = a.h < 4.0 * max(along, 0.0) * length(normalize(edge) - v);
    float s0 = 0.0;  // slice 0 starts at the camera, as integrate.comp takes it
    for (int z = 0; z < g.z; ++z) {
        float s1 = sliceZ(float(z + 1)) * perZ;
        float u0 = max(s0, t0), u1 = min(s1, t1);
        vec3 s = vec3(0.0);
        float unshadowed = 0.0;
        if (u0 < u1) {
            a.sum = vec3(0.0);
            advance(a, u1, vec3(1.0));
            vec3 V = vec3(1.0);
            // The temporal mode moves the shadow's point along the slice's lit part from frame to
            // frame, so the history averages the shadow and cookie over it.
            applyShadowAndColor(C + mix(u0, u1, froxelSlabPoint(ivec3(column, z))) * v, V);
            vec3 lin = finishInscatter(a, v);
            s = perUnitLength(V * lin, s0, s1);
            unshadowed = channelMean(perUnitLength(lin, s0, s1));
            if (besideLight && along >= s0 && along <= s1) {
                vec3 mean = vec3(0.0);
                for (int k = 0; k < 4; ++k) {
                    vec2 o = vec2((k & 1) == 0 ? 0.25 : 0.75, (k & 2) == 0 ? 0.25 : 0.75);
                    vec3 w = rayDirection(columnNdc(vec2(column), o));
                    float wz = 1.0 / axisCosine(w);
                    mean += 0.25 * slabScattering(C, w, s0 / perZ * wz, s1 / perZ * wz);
                }
                vec3 bounded = min(s, 2.0 * mean);
                unshadowed *= channelMean(bounded) / max(channelMean(s), 1e-30);
                s = bounded;
            }
        }
        store(ivec3(column, z), s, unshadowed);
        s0 = s1;
    }
}
#else
void main() {
    ivec3 g = ivec3(pc.grid.xyz);
    ivec3 f = ivec3(gl_GlobalInvocationID);
    if (!kFirstLight) f.xy += ivec2(pc.columns.xy);
    if (any(greaterThanEqual(f, g))) return;
    vec3 s = vec3(0.0);
    if (reachesColumn(f.xy)) {
        vec3 j = froxelJitter(f);
        vec3 v = rayDirection(columnNdc(vec2(f.xy), j.xy));
        float z = sliceZ(float(f.z) + j.z);
        vec3 P = frame.cameraPos.xyz + v * (z / axisCosine(v));
        float cosTheta;
        vec3 irr = lightAt(P, v, 0.0, cosTheta);
        s = phaseSum(cosTheta) * irr;
    }
    store(f, s, -1.0);
}
#endif
