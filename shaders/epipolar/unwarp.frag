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

// Seed 000's bilateral filter of the 2 x 2 samples nearest the pixel (ndc p, camera z): true when
// samples of the pixel's depth served it, value then their weighted mean; else value holds the
// plain bilinear mean of the valid samples (0 without any).
bool filterSamples(vec2 p, float z, out vec4 value) {
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
        // Outside the light's window (its lines cover only its wedge) there is no sample.
        int slice = windowSlice(int(j0f) + a);
        if (slice >= slices) continue;
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
            vec4 texel = texelFetch(inscatter, s, 0);
            // Alpha: how much the sample's value means (0 for a fraction of nothing).
            float w = ws * (b == 0 ? 1.0 - wk : wk) * texel.a;
            if (sz <= 0.0 || w <= 0.0) continue;  // not a valid sample
            plain += w * texel;
            plainWeight += w;
            if (abs(sz - z) <= epipolar.unwarp.x * z) {
                sum += w * texel;
                weight += w;
            }
        }
    }
    bool served = weight > 1e-3;
    value = served ? sum / weight : (plainWeight > 0.0 ? plain / plainWeight : vec4(0.0));
    return served;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec2 p = pixelToNdc(vec2(pixel) + 0.5);
    float z = pixelCameraZ(depthBuffer, pixel);
    vec3 v = rayDirection(p);
    float S = rayLength(z, v);
    vec3 C = frame.cameraPos.xyz;
    float t0, t1;
    lightInterval(C, v, S, t0, t1);
    // A ray the light cannot reach (outside a spot's cone or its range) has Lin 0, as the
    // fix-up's march would find. In ratio mode every sample's fraction is scaled by that 0: no
    // search. In Lin mode the samples still speak where they can (the image stays the same), and
    // where they cannot the pixel is served as 0 rather than left to the fix-up.
    bool dark = !(t0 < t1);
    // Outside the light's screen rectangle no ray reaches its volume and no line runs.
    bool nothing = (dark && carriesShadowedFraction()) || !insideBoundary(p, 1e-5);
    vec4 value = vec4(0.0);
    if (!nothing) {
        bool served = filterSamples(p, z, value);
        nothing = dark && !served && pc.fixup != 0;
        // The fix-up's pixel: no store, and no stencil mark (the discard keeps the stencil at 0).
        if (pc.fixup != 0 && !served && !nothing) discard;
    }
    if (nothing) {
        if (pc.addOnly != 0) {  // a later light adds 0: nothing to store
            compositeKeep();
            return;
        }
        value = vec4(0.0);
    }
    if (carriesShadowedFraction()) {
        value.rgb *= unshadowedInscatter(C, v, t0, t1);
    } else {
        value.rgb = loadedLin(value.rgb);  // the samples' Lin, as the ray march stored it
    }
    compositeInto(pixel, value.rgb, S, pc.addOnly != 0);
}
