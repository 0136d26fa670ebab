// Shadow-map visibility in the standard depth convention (reversed maps are flipped on read), with
// the footprint the min/max trees are built from: the 2x2 texels around the sample, clamped to the
// map. Outside the map a point counts as lit; ray depths are clamped to [0, 1].
// Needs `shadowMap` (sampler2D) declared by the including shader; with LS_CUBE_SHADOW, a point
// light's cube map as a sampler2DArray of six layers (faces +X, -X, +Y, -Y, +Z, -Z), of which the
// look-ups read layer `shadowFace`.
#ifndef LS_SHADOW_GLSL
#define LS_SHADOW_GLSL
#include "frame.glsl"

float toStandardDepth(float z) { return frame.shadowInfo.z > 0.5 ? 1.0 - z : z; }
vec4 toStandardDepth(vec4 z) { return frame.shadowInfo.z > 0.5 ? 1.0 - z : z; }

#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
int shadowFace = 0;  // the cube face (layer) the look-ups below read
float shadowFetch(ivec2 p) { return texelFetch(shadowMap, ivec3(p, shadowFace), 0).r; }
#elif defined(LS_NO_SHADOW_MAP) && LS_NO_SHADOW_MAP
// A march without a shadow map (an unshadowed light whose color varies along the ray): there is
// no map to read, and shadowFootprint() puts every point outside it, so every point is lit.
float shadowFetch(ivec2 p) { return 1.0; }
#else
float shadowFetch(ivec2 p) { return texelFetch(shadowMap, p, 0).r; }
#endif

float shadowTexel(ivec2 p) {
    int size = int(frame.shadowInfo.x);
    return toStandardDepth(shadowFetch(clamp(p, ivec2(0), ivec2(size - 1))));
}

// The standard depths of texels i, i + (1, 0), i + (0, 1) and i + (1, 1), each clamped to the map
// (i from -1 to size - 1): one gather at the corner the four share, where a device's fixed-point
// choice of the 2 x 2 texels is half a texel from any other (the sampler clamps to the edge, as
// shadowTexel does). On lavapipe one gather costs less than four fetches.
vec4 shadowQuad(ivec2 i) {
#if defined(LS_NO_SHADOW_MAP) && LS_NO_SHADOW_MAP
    return vec4(1.0);
#else
    vec2 corner = vec2(i + 1) / frame.shadowInfo.x;
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
    vec4 g = textureGather(shadowMap, vec3(corner, float(shadowFace)), 0);
#else
    vec4 g = textureGather(shadowMap, corner, 0);
#endif
    // Gathered as (i0, j1), (i1, j1), (i1, j0), (i0, j0).
    return toStandardDepth(vec4(g.w, g.z, g.x, g.y));
#endif
}

bool outsideShadowMap(vec2 uv) { return any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))); }

// The ray's depth as compared: standard convention, clamped, plus the bias.
float compareDepth(float zStandard) { return clamp(zStandard, 0.0, 1.0) + frame.shadowInfo.w; }

// The texels shadowVisibility(uv, .) reads and their bilinear weights: a point at uv whose
// compared depth is z is lit through texel k when z <= depth[k]. The ray march splits a step where
// the ray's depth passes one of them (march.glsl, advanceThroughFootprint).
struct ShadowFootprint {
    bool inside;  // outside the map every point is lit
    vec4 depth;   // the 2x2 texels' standard depths (i, i + x, i + y, i + xy); one texel's, nearest
    vec2 f;       // where uv lies between them (0 with the nearest filter)
};

ShadowFootprint shadowFootprint(vec2 uv) {
    ShadowFootprint s;
#if defined(LS_NO_SHADOW_MAP) && LS_NO_SHADOW_MAP
    s.inside = false;
#else
    s.inside = !outsideShadowMap(uv);
#endif
    s.depth = vec4(1.0);
    s.f = vec2(0.0);
    if (!s.inside) return s;
    float size = frame.shadowInfo.x;
    if (!kBilinearShadow) {
        s.depth = vec4(shadowTexel(ivec2(floor(uv * size))));
        return s;
    }
    vec2 p = uv * size - 0.5;
    ivec2 i = ivec2(floor(p));
    s.f = p - floor(p);
    s.depth = shadowQuad(i);
    return s;
}

// Fraction of the light reaching a point of the footprint whose compared depth (compareDepth) is z.
float footprintVisibility(ShadowFootprint s, float z) {
    if (!s.inside) return 1.0;
    vec4 lit = vec4(lessThanEqual(vec4(z), s.depth));
    return mix(mix(lit.x, lit.y, s.f.x), mix(lit.z, lit.w, s.f.x), s.f.y);
}

// Fraction of the light reaching a point at shadow-map position uv and standard depth z.
float shadowVisibility(vec2 uv, float zStandard) {
    return footprintVisibility(shadowFootprint(uv), compareDepth(zStandard));
}

// Min and max depth over every texel shadowVisibility(uv, .) can read (1.0 outside the map).
vec2 shadowFootprintMinMax(vec2 uv) {
    if (outsideShadowMap(uv)) return vec2(1.0);
    vec4 q = shadowQuad(ivec2(floor(uv * frame.shadowInfo.x - 0.5)));
    return vec2(min(min(q.x, q.y), min(q.z, q.w)), max(max(q.x, q.y), max(q.z, q.w)));
}

#endif
