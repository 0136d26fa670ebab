// Accumulates Lin along one ray, segment by segment, with one exponential (directional) or one
// exponential and one table look-up (point, spot) per step. Differences of exponentials go through
// expm1 (docs/model.md). Visibility may be colored (stained glass). In a non-uniform medium
// (kMedia != 0) the sun's segments stay exact given their optical depths, and a point or spot
// light's are cut into pieces that the table integrates without extinction and that the medium
// weighs at their middles.
#ifndef LS_INTEGRATE_GLSL
#define LS_INTEGRATE_GLSL
#include "light_falloff.glsl"
#include "math.glsl"
#include "medium.glsl"
#if LS_NEEDS_TABLE
#include "lut.glsl"
#endif

struct Inscatter {
    vec3 sum;    // directional: sum of exp(-betaT a) w V; point/spot: sum of (F(a) - F(b)) V
    vec3 carry;  // directional: exp(-betaT d); point/spot: F(d) = exp(-betaT d) T(h, sC + d)
    float d;     // where the last segment ended, metres from the camera
    float h;     // point/spot: the light's distance from the ray's line
    float sC;    // point/spot: the camera's coordinate along the ray, from the light's projection
    // A light with a smooth falloff (light_falloff.glsl): segments go in pieces of at most this
    // length, each weighted by the falloff at its middle, on the ray from C along v; 0: none.
    float piece;
    vec3 C, v;
    float tau;  // a non-uniform medium: the optical depth from the camera to d
};

vec3 carryAt(Inscatter a, float d) {
#if LS_NEEDS_TABLE
    if (kLightType != LIGHT_DIRECTIONAL && kMedia != 0) return pointTableT(a.h, a.sC + d);
    if (kLightType != LIGHT_DIRECTIONAL)
        return exp(-frame.betaT.rgb * d) * pointTableT(a.h, a.sC + d);
#endif
    if (kMedia != 0) return exp(-frame.betaT.rgb * a.tau);
    return exp(-frame.betaT.rgb * d);
}

Inscatter beginInscatter(vec3 C, vec3 v, float d0) {
    Inscatter a;
    a.sum = vec3(0.0);
    a.d = d0;
    a.h = 0.0;
    a.sC = 0.0;
    a.piece = 0.0;
    a.C = C;
    a.v = v;
    if (kLightType != LIGHT_DIRECTIONAL) {
        vec3 q = C - frame.lightPos.xyz;
        a.h = length(cross(v, q));  // never sqrt(|q|^2 - b^2): that cancels
        a.sC = dot(v, q);
        a.piece = falloffPiece(a.h);
    }
    a.tau = kMedia != 0 ? opticalDepth(C, v, d0) : 0.0;
    // A sun's ray from the camera starts at 1, exp(0), without the three exponentials, which the
    // unwarp's per-pixel closed form would run for every pixel (docs/epipolar.md, "Where the
    // unwarp's time goes"); a branch, so that a block of lanes that all start at 0 skips them.
    if (kLightType == LIGHT_DIRECTIONAL && kMedia == 0 && d0 == 0.0)
        a.carry = vec3(1.0);
    else
        a.carry = carryAt(a, d0);
    return a;
}

// A point or spot light's [a.d, d] in a non-uniform medium. The table (without extinction) holds
// the sharp part, the inverse square and the phase, exactly; each piece's share of it is weighed
// by the piece's mean density (its optical depth over its length) and the transmittance along the
// camera ray and the light's path at its middle. Pieces are even in the angle seen from the light,
// where the inverse square puts equal shares (32 to a half turn), and no longer than the medium's
// scale (a hard box's faces included: a piece straddling a face lends the box's density to the
// part of the beam outside it, in proportion to the piece's length).
void advanceNonUniform(inout Inscatter a, float d, vec3 V) {
    // In clear air (d0 = 0) only the volumes scatter or dim: the stretch before the first and
    // after the last is skipped (its optical depth is 0), and the pieces go where the fog is.
    float end = d;
    if (frame.medium.x <= 0.0) {
        float start = a.d;
        clipToMedium(a.C, a.v, start, end);
        if (!(start < end)) start = end = d;
        if (start > a.d) {
            a.d = start;
            a.carry = carryAt(a, start);
        }
    }
    float r0 = frame.betaT.w;
    float hEff = sqrt(a.h * a.h + r0 * r0);
    float phiA = atan(a.sC + a.d, hEff), phiB = atan(a.sC + end, hEff);
    float len = end - a.d;
    float pieces = max(len / frame.mediumScale.x, (phiB - phiA) * (32.0 / PI));
    if (a.piece > 0.0) pieces = max(pieces, len / a.piece);
    int n = int(clamp(ceil(pieces), 1.0, 32.0));
    for (int k = 0; k < n && a.d < end; ++k) {
        float e = k == n - 1 ? end
                             : clamp(hEff * tan(mix(phiA, phiB, float(k + 1) / float(n))) - a.sC,
                                     a.d, end);
        float l = e - a.d;
        vec3 next = carryAt(a, e);
        float dtau = opticalDepth(a.C + a.d * a.v, a.v, l);
        vec3 mid = a.C + (0.5 * (a.d + e)) * a.v;
        float meanDensity = l > 0.0 ? dtau / l : densityAt(mid);
        vec3 w = meanDensity *
                 exp(-frame.betaT.rgb * (a.tau + 0.5 * dtau + opticalDepthTo(mid, frame.lightPos.xyz)));
        if (a.piece > 0.0) w *= lightFalloff(mid);
        a.sum += (a.carry - next) * V * w;
        a.carry = next;
        a.tau += dtau;
        a.d = e;
    }
    if (a.d < d) {
        a.d = d;
        a.carry = carryAt(a, d);
    }
}

// A sun's step to d, lit with V or shadowed: one optical depth (the length in a uniform medium) and
// one exponential serve both. Exact whatever m is: dT/ds = -betaT m T, so a lit run gives
// T(a) (1 - exp(-betaT dtau)) / betaT of the optical depth dtau it spans, and T(d) = T(a)
// exp(-betaT dtau) comes from the same expm1.
void sunStep(inout Inscatter a, float d, vec3 V, bool shadowed) {
    if (d <= a.d) return;
    float len = kMedia != 0 ? opticalDepth(a.C + a.d * a.v, a.v, d - a.d) : d - a.d;
    vec3 beta = frame.betaT.rgb;
    vec3 em1 = expm1v(-beta * len);
    if (shadowed) {
        a.carry += a.carry * em1;
    } else {
        vec3 part = a.carry * attenuatedLengthFrom(beta, len, em1);
        a.sum += part * V;
        a.carry -= part * beta;
    }
    if (kMedia != 0) a.tau += len;
    a.d = d;
}

// Adds the segment [a.d, d] lit with visibility V.
void advance(inout Inscatter a, float d, vec3 V) {
    if (d <= a.d) return;
    if (kLightType == LIGHT_DIRECTIONAL) {
        sunStep(a, d, V, false);
    } else if (kMedia != 0) {
        advanceNonUniform(a, d, V);
    } else if (a.piece > 0.0) {
        int n = falloffPieces(d - a.d, a.piece);
        float step = (d - a.d) / float(n);
        for (int k = 0; k < n; ++k) {
            float e = k == n - 1 ? d : a.d + step;
            vec3 next = carryAt(a, e);
            a.sum += (a.carry - next) * V * lightFalloff(a.C + (0.5 * (a.d + e)) * a.v);
            a.carry = next;
            a.d = e;
        }
    } else {
        vec3 next = carryAt(a, d);
        a.sum += (a.carry - next) * V;
        a.carry = next;
    }
    a.d = d;
}

// Moves to d across a shadowed segment.
void skip(inout Inscatter a, float d) {
    if (kLightType == LIGHT_DIRECTIONAL) {
        sunStep(a, d, vec3(0.0), true);
        return;
    }
    if (d <= a.d) return;
    if (kMedia != 0) a.tau += opticalDepth(a.C + a.d * a.v, a.v, d - a.d);
    a.carry = carryAt(a, d);
    a.d = d;
}

// advance (lit with V) or skip (shadowed), for a march that decides which at run time: lavapipe
// runs both branches of an if whichever its lanes take, and a sun's step (sunStep) takes its
// optical depth and exponential once for both.
void advanceOrSkip(inout Inscatter a, float d, vec3 V, bool shadowed) {
    if (kLightType == LIGHT_DIRECTIONAL)
        sunStep(a, d, V, shadowed);
    else if (shadowed)
        skip(a, d);
    else
        advance(a, d, V);
}

vec3 finishInscatter(Inscatter a, vec3 v) {
    vec3 L = frame.lightIntensity.rgb;
    if (kLightType == LIGHT_DIRECTIONAL) return a.sum * L * phaseSum(dot(v, -frame.lightDir.xyz));
    return max(a.sum, vec3(0.0)) * L;
}

// Lin over [t0, t1] as if nothing cast a shadow (the light's own volume still applies).
vec3 unshadowedInscatter(vec3 C, vec3 v, float t0, float t1) {
    if (!(t0 < t1)) return vec3(0.0);
    Inscatter a = beginInscatter(C, v, t0);
    advance(a, t1, vec3(1.0));
    return finishInscatter(a, v);
}

// What epipolar interpolation carries in ratio mode: the shadowed fraction of the unshadowed Lin,
// per channel (1 where the unshadowed Lin is 0, so it blends neutrally).
vec3 shadowedFraction(vec3 lin, vec3 unshadowed) {
    vec3 r = lin / max(unshadowed, vec3(1e-30));
    return mix(clamp(r, 0.0, 1.0), vec3(1.0), lessThanEqual(unshadowed, vec3(0.0)));
}

#endif
