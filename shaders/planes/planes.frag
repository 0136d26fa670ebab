#version 450
#extension GL_GOOGLE_include_directive : require
// One plane's share of Lin at one pixel: the integrand of docs/model.md at the plane's point
// (transmittance to the camera, phase function, the light's irradiance, shadow-map visibility,
// light color as the seed's cookie) times the length of ray between two planes, spacing / cos of
// the ray's angle to the view axis (towardCamera and lightAt: seed 004's simplified model with
// kSimplifiedModel). The seed's scrolling noise multiplies the density. Planes
// behind the scene never get here: the engine's depth rejects them.
// LS_SLAB (beam-tree-sampling's planes near a point or spot light: those within a few spacings of
// its depth, thinner than the others, which the CPU draws apart), where the inverse
// square peaks inside one slab and the midpoint rule misses or overshoots the peak, a plane stands
// for the slab of ray between its neighbours' midpoints, cut to the light's volume, and its share
// is the closed form of the unshadowed Lin over it (integrate.glsl, the point-light table) times
// the visibility and light color at its middle: only the shadow is sampled. Other planes, a
// non-uniform medium and seed 004's simplified model keep the midpoint rule.
#ifndef LS_SLAB
#define LS_SLAB 0
#endif
#include "camera.glsl"
#include "math.glsl"
#include "plane_push.glsl"
#include "planes_bindings.h"
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
#if LS_NOISE
layout(binding = LS_BINDING_NOISE) uniform sampler2D noiseMap;  // repeating
#endif

layout(constant_id = LS_SPEC_PLANES_CHANNELS) const bool kChannels = false;
// 8-bit target: round each plane's share to the target's grid up or down at random, in proportion
// (stochastic rounding), so that shares below half a step add up on average instead of vanishing.
layout(constant_id = LS_SPEC_PLANES_DITHER) const bool kDither = false;

layout(location = 0) in vec3 fromCamera;  // the plane's point from the camera (planes.vert)
layout(location = 1) flat in int plane;
layout(location = 0) out vec4 outShare;

const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);

#if LS_NOISE
// Coordinates projected from the light: across a directional light's beam in metres, by angle
// (tangent) from a point or spot light, on the cube face it faces for a point light.
vec2 noiseCoordinates(vec3 P) {
    vec3 a = frame.lightDir.xyz;
    vec3 helper = abs(a.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 r = normalize(cross(a, helper)), u = cross(r, a);
    if (kLightType == LIGHT_DIRECTIONAL) return vec2(dot(P, r), dot(P, u));
    vec3 D = P - frame.lightPos.xyz;
    if (kLightType == LIGHT_SPOT) return vec2(dot(D, r), dot(D, u)) / max(dot(D, a), 1e-6);
    vec3 m = abs(D);
    if (m.x >= m.y && m.x >= m.z) return D.yz / m.x;
    if (m.y >= m.z) return D.xz / m.y;
    return D.xy / m.z;
}

// Mean 1 for independent layers of mean 1/2; amplitude 0 gives exactly 1.
float densityNoise(vec3 P) {
    vec2 q = noiseCoordinates(P) * placement.params.z;
    float n1 = texture(noiseMap, q + placement.noise.xy).r;
    float n2 = texture(noiseMap, q * 1.37 + vec2(0.31, 0.73) + placement.noise.zw).g;
    return max(1.0 + placement.params.y * (4.0 * n1 * n2 - 1.0), 0.0);
}
#endif

// A uniform number in [0, 1) per pixel and plane.
float planeHash(uvec2 p, uint k) {
    uint h = p.x * 0x8da6b343u ^ p.y * 0xd8163841u ^ k * 0xcb1ab31fu;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return float(h >> 8) / 16777216.0;
}

// The share of the plane's slab of ray [s - ds/2, s + ds/2], cut to the light's volume, in closed
// form (LS_SLAB); false where no light reaches it.
bool slabShare(vec3 C, vec3 v, float s, float ds, out vec3 share) {
    share = vec3(0.0);
#if LS_SLAB
    float t0, t1;
    lightInterval(C, v, min(s + 0.5 * ds, placement.params.w), t0, t1);
    // The frontmost slab also stands for the ray's head, from the camera to the planes' box, which
    // no plane samples: with the light at or beside the camera its glow lies there.
    float start = s - 0.5 * ds;
    float front = placement.boxMin.z / max(dot(v, frame.cameraForward.xyz), 1e-4);
    if (start <= front + 0.25 * ds) start = 0.0;
    t0 = max(t0, max(start, 0.0));
    if (!(t0 < t1)) return false;
    vec3 V = vec3(1.0);
    applyShadowAndColor(C + (0.5 * (t0 + t1)) * v, V);
    share = V * unshadowedInscatter(C, v, t0, t1);
    return true;
#else
    return false;
#endif
}

void main() {
    vec3 C = frame.cameraPos.xyz;
    float s = length(fromCamera);
    if (s > placement.params.w) discard;  // past the sky distance
    vec3 v = fromCamera / s;
    vec3 worldPos = C + fromCamera;
    float ds = placement.boxMin.w / max(dot(v, frame.cameraForward.xyz), 1e-4);
    vec3 share;
    if (LS_SLAB != 0 && kMedia == 0 && !kSimplifiedModel && kLightType != LIGHT_DIRECTIONAL &&
        placement.params.x == 0.0) {
        if (!slabShare(C, v, s, ds, share)) discard;
    } else {
        float cosTheta;
        vec3 irr = lightAt(worldPos, v, placement.params.x, cosTheta);
        if (all(equal(irr, vec3(0.0)))) discard;
        share = towardCameraFrom(worldPos, s, cosTheta) * irr * ds;
    }
#if LS_NOISE
    share *= densityNoise(worldPos);
#endif
    if (kChannels) {
        vec4 mask = vec4(equal(ivec4(plane & 3), ivec4(0, 1, 2, 3)));
        float value = dot(share, kLuminance) * placement.boxMax.w;
        if (kDither) value = floor(value * 255.0 + planeHash(uvec2(gl_FragCoord.xy), uint(plane))) / 255.0;
        outShare = mask * value;
    } else {
        outShare = vec4(storedLin(share), 0.0);
    }
}
