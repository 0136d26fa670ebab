#version 450
#extension GL_GOOGLE_include_directive : require
// Epipolar -> screen (seed 000): find the slice through the pixel and its place along it, and
// filter the 2 x 2 nearest samples bilaterally (weights zeroed where their camera z differs from
// the pixel's), and composite the result into the engine's color (composite_into.glsl): no
// screen-sized Lin texture and no composite pass. With fix-up, a pixel no sample can serve is
// discarded before it stores anything, so the camera stencil ends up 1 exactly where the unwarp
// served the pixel and the fix-up takes the zeros: one draw searches the samples once. Without
// fix-up such pixels fall back to plain bilinear weights.
// In ratio mode the samples carry the shadowed fraction, and the pixel's own unshadowed Lin (closed
// form) scales it back: the glow around a light, which no sparse sampling resolves, stays exact.
#include "epipolar_geometry.glsl"
#include "camera.glsl"
#include "epipolar_bindings.h"
layout(binding = LS_BINDING_UNWARP_END_POINTS) uniform sampler2D sliceEndPoints;
layout(binding = LS_BINDING_UNWARP_EPIPOLAR_Z) uniform sampler2D epipolarZ;
layout(binding = LS_BINDING_UNWARP_INSCATTER) uniform sampler2D inscatter;
layout(binding = LS_BINDING_UNWARP_DEPTH) uniform sampler2D depthBuffer;  // the engine's depth
#if LS_NEEDS_TABLE
layout(binding = LS_BINDING_POINT_TABLE) uniform sampler2D pointTable;
#endif
#include "integrate.glsl"
#include "light_volume.glsl"
#include "composite_into.glsl"
#define LS_INT int
layout(push_constant) uniform Push {
#include "unwarp_push_fields.h"
} pc;
#undef LS_INT

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec2 p = pixelToNdc(vec2(pixel) + 0.5);
    float z = pixelCameraZ(depthBuffer, pixel);
    vec2 light = frame.lightScreen.xy;
    vec2 d = p - light;
    if (dot(d, d) < 1e-12) d = vec2(1e-6, 0.0);
    float tNear, tFar;
    int edge;
    boundaryRange(light, d, tNear, tFar, edge);
    float sliceF = sliceOfExitPoint(light + tFar * d, edge);
    int slices = int(epipolar.sampling.x);
    int samples = int(epipolar.sampling.y);
    float j0f = floor(sliceF);
    float sliceW = sliceF - j0f;

    vec4 sum = vec4(0.0), plain = vec4(0.0);
    float weight = 0.0, plainWeight = 0.0;
    for (int a = 0; a < 2; ++a) {
        int slice = (int(j0f) + a + slices) % slices;
        float ws = a == 0 ? 1.0 - sliceW : sliceW;
        vec4 ends = texelFetch(sliceEndPoints, ivec2(slice, 0), 0);
        if (ends.x <= INVALID_SLICE + 1.0 || ws <= 0.0) continue;
        vec2 line = ends.zw - ends.xy;
        float k = dot(p - ends.xy, line) / max(dot(line, line), 1e-20) * float(samples - 1);
        k = clamp(k, 0.0, float(samples - 1));
        int k0 = min(int(floor(k)), samples - 2);
        float wk = k - float(k0);
        for (int b = 0; b < 2; ++b) {
            ivec2 s = ivec2(k0 + b, slice);
            float sz = texelFetch(epipolarZ, s, 0).r;
            vec4 value = texelFetch(inscatter, s, 0);
            // Alpha: how much the sample's value means (0 for a fraction of nothing).
            float w = ws * (b == 0 ? 1.0 - wk : wk) * value.a;
            if (sz <= 0.0 || w <= 0.0) continue;  // not a valid sample
            plain += w * value;
            plainWeight += w;
            if (abs(sz - z) <= epipolar.unwarp.x * z) {
                sum += w * value;
                weight += w;
            }
        }
    }
    bool resolved = weight > 1e-3;
    // The fix-up's pixel: no store, and no stencil mark (the discard keeps the stencil at 0).
    if (pc.fixup != 0 && !resolved) discard;
    vec4 value = resolved ? sum / weight : (plainWeight > 0.0 ? plain / plainWeight : vec4(0.0));
    vec3 v = rayDirection(p);
    float S = rayLength(z, v);
    if (carriesShadowedFraction()) {
        vec3 C = frame.cameraPos.xyz;
        float t0, t1;
        lightInterval(C, v, S, t0, t1);
        value.rgb *= unshadowedInscatter(C, v, t0, t1);
    } else {
        value.rgb = loadedLin(value.rgb);  // the samples' Lin, as the ray march stored it
    }
    compositeInto(pixel, value.rgb, S, pc.addOnly != 0);
}
