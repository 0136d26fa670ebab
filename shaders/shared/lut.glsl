// The point-light table of seed 000 (docs/model.md): T(h, s) = integral over [s, inf) of
// P(theta) exp(-betaT (x - s)) exp(-betaT sqrt(h^2 + x^2)) / (h^2 + x^2 + r0^2) dx, with x measured
// along the ray from the light's projection onto it. Stored as G = hEff T, hEff = sqrt(h^2 + r0^2),
// over (phi, y): s = hEff tan(phi), phi in [-pi/2, pi/2] across the width (end points included);
// log(hEff / r0) down the height, row i at i / (height - 1) * logRange (lutInfo.x).
// Needs `pointTable` (sampler2D) declared by the including shader.
#ifndef LS_LUT_GLSL
#define LS_LUT_GLSL
#include "frame.glsl"

vec3 tableFetch(ivec2 p) {
    ivec2 size = ivec2(frame.lutInfo.yz);
    return texelFetch(pointTable, clamp(p, ivec2(0), size - 1), 0).rgb;
}

// T(h, s), already divided by hEff.
vec3 pointTableT(float h, float s) {
    float r0 = frame.betaT.w;
    float hEff = sqrt(h * h + r0 * r0);
    float phi = atan(s, hEff);
    vec2 size = frame.lutInfo.yz;
    float x = (phi / PI + 0.5) * (size.x - 1.0);
    float y = log(max(hEff / r0, 1.0)) / frame.lutInfo.x * (size.y - 1.0);
    vec2 p = vec2(x, y);
    ivec2 i = ivec2(floor(p));
    vec2 f = p - floor(p);
    vec3 g = mix(mix(tableFetch(i), tableFetch(i + ivec2(1, 0)), f.x),
                 mix(tableFetch(i + ivec2(0, 1)), tableFetch(i + ivec2(1, 1)), f.x), f.y);
    return g / hEff;
}

#endif
