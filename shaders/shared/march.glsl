// Per-pixel ray marching through the shadow map, one step per texel crossed (seed 000's starting
// point): the brute-force method and the epipolar fix-up. The ray is clipped to the light's volume
// and to the shadow map's frustum; the parts outside the frustum are lit and integrated in closed
// form. Attributes are interpolated perspective-correctly in light space (1/w and d/w are affine).
#ifndef LS_MARCH_GLSL
#define LS_MARCH_GLSL
#include "integrate.glsl"
#include "light_color.glsl"
#include "light_volume.glsl"
#include "shadow.glsl"

// Adds [f0, f1] (inside the shadow map's frustum) to acc, one step per texel crossed (at most
// maxSteps when that is not 0), each step's visibility taken at its end.
void marchFrustumSegment(inout Inscatter acc, vec3 C, vec3 v, float f0, float f1, uint maxSteps) {
    vec4 X0 = frame.lightViewProj * vec4(C + f0 * v, 1.0);
    vec4 X1 = frame.lightViewProj * vec4(C + f1 * v, 1.0);
    vec2 uv0 = X0.xy / X0.w * 0.5 + 0.5, uv1 = X1.xy / X1.w * 0.5 + 0.5;
    float z0 = toStandardDepth(X0.z / X0.w), z1 = toStandardDepth(X1.z / X1.w);
    float iw0 = 1.0 / X0.w, iw1 = 1.0 / X1.w;
    vec2 span = abs(uv1 - uv0) * frame.shadowInfo.x;
    uint n = uint(max(1.0, ceil(max(span.x, span.y))));
    if (maxSteps > 0u) n = min(n, maxSteps);
    for (uint k = 1u; k <= n; ++k) {
        float a = float(k) / float(n);
        vec2 uv = mix(uv0, uv1, a);
        float d = k == n ? f1 : mix(f0 * iw0, f1 * iw1, a) / mix(iw0, iw1, a);
        advance(acc, d, shadowVisibility(uv, mix(z0, z1, a)) * lightColorAt(uv));
    }
}

// Lin along C + d v, d in [0, S]; maxSteps 0 means one step per texel.
vec3 marchRay(vec3 C, vec3 v, float S, uint maxSteps) {
    float t0, t1;
    lightInterval(C, v, S, t0, t1);
    if (!(t0 < t1)) return vec3(0.0);
    Inscatter acc = beginInscatter(C, v, t0);
    float f0 = t0, f1 = t1;
    clipToShadowFrustum(C, v, f0, f1);
    if (f0 < f1) {
        advance(acc, f0, vec3(1.0));
        marchFrustumSegment(acc, C, v, f0, f1, maxSteps);
    }
    advance(acc, t1, vec3(1.0));
    return finishInscatter(acc, v);
}

#endif
