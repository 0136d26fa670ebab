#version 450
#extension GL_GOOGLE_include_directive : require
// Turns the planes' sum into Lin: the four 8-bit channels summed and tinted (kChannels), seed
// 002's blur at composite (kBlurRadius pixels, a 5x5 tent of bilinear taps), and for a directional
// light the parts of each ray in front of and behind the planes' slab, in closed form: that light
// reaches everywhere, and outside the shadow map's box nothing shadows it.
#include "camera.glsl"
#include "integrate.glsl"
#include "planes_bindings.h"
layout(binding = LS_BINDING_DEPTH) uniform sampler2D depthBuffer;  // the engine's depth
layout(binding = LS_BINDING_PLANE_SUM) uniform sampler2D planeSum;  // linear, clamped

layout(constant_id = LS_SPEC_RESOLVE_CHANNELS) const bool kChannels = false;
layout(constant_id = LS_SPEC_RESOLVE_BLUR_RADIUS) const int kBlurRadius = 0;
layout(constant_id = LS_SPEC_RESOLVE_CLOSED_FORM_OUTSIDE_SLAB) const bool kClosedFormOutsideSlab = false;

#define LS_VEC4 vec4
#define LS_INIT(x)
layout(push_constant) uniform ResolvePush {
#include "plane_resolve_push_fields.h"
} resolve;
#undef LS_VEC4
#undef LS_INIT

layout(location = 0) out vec4 outInscatter;

// The planes' sum is as large as the screen-sized textures (the plugin's maxRenderSize): the
// screen's coordinates scale by its share of them (exactly 1 without a maximum), and the taps stay
// on the screen's texels, as the sampler's clamp to the edge keeps them without one.
vec4 planeSumAt(vec2 pixelCenter) {
    vec2 uv = pixelCenter * frame.screenSize.zw;
    if (kBlurRadius == 0) return texelFetch(planeSum, ivec2(pixelCenter), 0);
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    float step = float(kBlurRadius) * 0.5;
    bool part = frame.screenTexels.z < 1.0 || frame.screenTexels.w < 1.0;
    vec2 lo = 0.5 / frame.screenTexels.xy, hi = frame.screenTexels.zw - lo;
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x) {
            float w = float(3 - abs(x)) * float(3 - abs(y));
            vec2 tap = (uv + vec2(x, y) * step * frame.screenSize.zw) * frame.screenTexels.zw;
            if (part) tap = clamp(tap, lo, hi);
            sum += w * textureLod(planeSum, tap, 0.0);
            weights += w;
        }
    return sum / weights;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 p = planeSumAt(gl_FragCoord.xy);
    // The float planes' sum is stored scaled already (storedLin); the 8-bit channels' is not.
    vec3 lin = kChannels ? (p.r + p.g + p.b + p.a) * resolve.tint.rgb : loadedLin(p.rgb);
    if (kClosedFormOutsideSlab && kLightType == LIGHT_DIRECTIONAL) {
        vec3 C = frame.cameraPos.xyz;
        vec3 v = pixelRayDirection(pixel);
        float S = rayLength(pixelCameraZ(depthBuffer, pixel), v);
        float c = max(dot(v, frame.cameraForward.xyz), 1e-4);
        lin += unshadowedInscatter(C, v, 0.0, min(S, resolve.slab.x / c));
        lin += unshadowedInscatter(C, v, resolve.slab.y / c, S);
    }
    outInscatter = vec4(storedLin(lin), 1.0);
}
