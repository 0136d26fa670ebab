// Phase functions and numerically careful exponentials (docs/model.md, "Numerical rules").
#ifndef LS_MATH_GLSL
#define LS_MATH_GLSL
#include "frame.glsl"

float phaseRayleigh(float c) { return 3.0 / (16.0 * PI) * (1.0 + c * c); }

float phaseCornetteShanks(float c, float g) {
    float g2 = g * g;
    float denom = max(1.0 + g2 - 2.0 * g * c, 1e-6);
    return 1.0 / (4.0 * PI) * 3.0 * (1.0 - g2) / (2.0 * (2.0 + g2)) * (1.0 + c * c) /
           (denom * sqrt(denom));
}

// Seed 004's hazy atmosphere, (1 + 9 cos^16(alpha / 2)) / (8 pi): cos^16(alpha / 2) = ((1 + c) / 2)^8.
float phaseHazy(float c) {
    float h = 0.5 * (1.0 + c), h2 = h * h, h4 = h2 * h2;
    return (1.0 + 9.0 * h4 * h4) / (8.0 * PI);
}

// betaR pR + betaM pM, per channel (1/(m sr)).
vec3 phaseSum(float cosTheta) {
    float mie = kMiePhase == LIGHTSCATTER_MIE_ISOTROPIC ? 1.0 / (4.0 * PI)
              : kMiePhase == LIGHTSCATTER_MIE_HAZY    ? phaseHazy(cosTheta)
                               : phaseCornetteShanks(cosTheta, frame.betaR.w);
    return frame.betaR.rgb * phaseRayleigh(cosTheta) + frame.betaM.rgb * mie;
}

// exp(x) - 1 without cancellation near 0 (GLSL has no expm1).
float expm1f(float x) {
    if (abs(x) < 0.25)
        return x * (1.0 + x * (1.0 / 2.0 + x * (1.0 / 6.0 + x * (1.0 / 24.0 + x * (1.0 / 120.0 +
               x * (1.0 / 720.0 + x * (1.0 / 5040.0)))))));
    return exp(x) - 1.0;
}
vec3 expm1v(vec3 x) { return vec3(expm1f(x.r), expm1f(x.g), expm1f(x.b)); }

// Integral of exp(-beta s) over [0, len]: (1 - exp(-beta len)) / beta, and len where beta is 0;
// given em1 = expm1(-beta len), for a caller that needs that exponential too.
vec3 attenuatedLengthFrom(vec3 beta, float len, vec3 em1) {
    vec3 w = -em1 / max(beta, vec3(1e-30));
    return mix(w, vec3(len), lessThanEqual(beta, vec3(0.0)));
}
vec3 attenuatedLength(vec3 beta, float len) {
    return attenuatedLengthFrom(beta, len, expm1v(-beta * len));
}

#endif
