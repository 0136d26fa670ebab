// Seed 004's simplified light model (Nilsson 2008, eqs. 2.12-2.17; Settings::lightModel): the
// irradiance at distance r from the light is I / (a1 r^2 + a0), nothing is attenuated on the way in
// or out, and the phase is isotropic, 1/(4 pi), for betaS = betaR + betaM. Along a ray C + s v its
// integral is one arctangent (2.17):
//     Lin = I betaS / (4 pi a1) * integral over [t0, t1] of ds / ((s + b)^2 + w^2)
// with q = C - L, b = dot(v, q), w^2 = |cross(v, q)|^2 + a0 / a1. With a1 = 1 and a0 = r0^2 it is
// seed 001's closed form (analytic.frag). frame.simplified holds a0 / a1 and 1 / a1.
#ifndef LS_SIMPLIFIED_GLSL
#define LS_SIMPLIFIED_GLSL
#include "frame.glsl"
#include "light_falloff.glsl"

// integral over [t0, t1] of ds / ((s + b)^2 + w^2) = (atan((t1 + b)/w) - atan((t0 + b)/w)) / w.
// The difference of arctangents is one angle: tan(x - y) = (X - Y)/(1 + X Y), and with
// t1 >= t0 the numerator is never negative, so atan2 picks the right quadrant; nothing cancels,
// whether the light lies before, within or behind the segment.
float arctanIntegral(float t0, float t1, float b, float w) {
    float num = (t1 - t0) * w;
    float den = w * w + (t0 + b) * (t1 + b);
    return atan(num, den) / w;
}

// The same integral with the light's smooth falloff (light_falloff.glsl) under it: in pieces, each
// weighted by the falloff at its middle; without one, the arctangent alone. h: the light's distance
// from the ray's line.
float falloffArctanIntegral(vec3 C, vec3 v, float t0, float t1, float b, float w, float h) {
    float piece = falloffPiece(h);
    if (piece <= 0.0) return arctanIntegral(t0, t1, b, w);
    int n = falloffPieces(t1 - t0, piece);
    float step = (t1 - t0) / float(n), sum = 0.0;
    for (int k = 0; k < n; ++k) {
        float a = t0 + float(k) * step, e = k == n - 1 ? t1 : a + step;
        sum += arctanIntegral(a, e, b, w) * lightFalloff(C + (0.5 * (a + e)) * v);
    }
    return sum;
}

// The simplified model's Lin over [t0, t1] of the ray from C along unit v, unshadowed (the caller
// limits [t0, t1] to the spot's cone and range).
vec3 simplifiedInscatter(vec3 C, vec3 v, float t0, float t1) {
    if (!(t0 < t1)) return vec3(0.0);
    vec3 q = C - frame.lightPos.xyz;
    float b = dot(v, q);
    vec3 h = cross(v, q);  // never |q|^2 - b^2, which cancels
    float w = sqrt(dot(h, h) + frame.simplified.x);
    vec3 betaS = frame.betaR.rgb + frame.betaM.rgb;
    float integral = falloffArctanIntegral(C, v, t0, t1, b, w, length(h));
    return frame.lightIntensity.rgb * betaS * (integral * frame.simplified.y / (4.0 * PI));
}

// The simplified model's irradiance factor 1 / (a1 r^2 + a0) at squared distance r2.
float simplifiedFalloff(float r2) { return frame.simplified.y / (r2 + frame.simplified.x); }

#endif
