// The composite, done where Lin is made: color = color * exp(-betaT S) + k Lin in the engine's
// image (k the engine's pre-exposure, 1 by default), and Lin alone, unexposed, into the output
// image when the frame asked for one. A frame's later lights (addOnly) add their Lin to both: the
// first light's composite applied the extinction. Each invocation touches its own pixel only. The
// color's format and the output image are build-time variants (LS_COLOR_RGBA32F, LS_WITH_OUTPUT):
// a storage image read needs its format.
// LS_BLEND (a fragment pass whose target blends: CompositeTarget::blend): the engine's color is
// the pass's color attachment under dual-source blending (dst * src1 + src0), and the shader
// writes k Lin and the transmittance as its two sources instead of reading and writing the
// storage image: the same sum in the same float arithmetic (the same bits on lavapipe), and the
// blender's work rather than a load and a store per pixel. Every invocation that keeps its
// fragment must then write both sources (compositeKeep: 0 and 1).
// LS_SPLIT: the engine's color is not a storage image this shader can write (an attachment-only,
// sRGB, packed or 8-bit target), or the frame asked for the transmittance: the composite goes
// into two images of the plugin's instead, k Lin (LS_BINDING_ENGINE_COLOR) and the transmittance
// (LS_BINDING_COMPOSITE_T), which the first light writes and later lights add to, and a last pass
// blends them into the engine's color (composite_blend.frag, composite_apply.comp):
// color * T + k Lin, the same sum.
#ifndef LS_COMPOSITE_INTO_GLSL
#define LS_COMPOSITE_INTO_GLSL
#include "camera.glsl"
#include "frame.glsl"
#include "medium.glsl"

#if defined(LS_BLEND) && LS_BLEND
layout(location = 0, index = 0) out vec4 compositeLin;           // src0: k Lin
layout(location = 0, index = 1) out vec4 compositeTransmittance;  // src1: the color's factor
#elif LS_COLOR_RGBA32F
layout(binding = LS_BINDING_ENGINE_COLOR, rgba32f) uniform image2D engineColor;
#else
layout(binding = LS_BINDING_ENGINE_COLOR, rgba16f) uniform image2D engineColor;
#endif
#if LS_WITH_OUTPUT
layout(binding = LS_BINDING_LIN_OUT, rgba32f) uniform image2D inscatterOut;
#endif
#if defined(LS_SPLIT) && LS_SPLIT
#if LS_COLOR_RGBA32F
layout(binding = LS_BINDING_COMPOSITE_T, rgba32f) uniform writeonly image2D compositeT;
#else
layout(binding = LS_BINDING_COMPOSITE_T, rgba16f) uniform writeonly image2D compositeT;
#endif
#endif

// With the transmittance given: color = color * transmittance + k Lin (froxels' grid holds it).
void compositeWith(ivec2 p, vec3 lin, vec3 transmittance, bool addOnly) {
    const vec3 exposed = lin * frame.linStorage.z;
#if defined(LS_BLEND) && LS_BLEND
    // Alpha: 0 + dst.a * 1, the color's own, as the read-modify-write below keeps it.
    compositeLin = vec4(exposed, 0.0);
    compositeTransmittance = vec4(addOnly ? vec3(1.0) : transmittance, 1.0);
#elif defined(LS_SPLIT) && LS_SPLIT
    // The first light writes every pixel of the frame: nothing earlier is read.
    if (addOnly) {
        imageStore(engineColor, p, vec4(imageLoad(engineColor, p).rgb + exposed, 1.0));
    } else {
        imageStore(engineColor, p, vec4(exposed, 1.0));
        imageStore(compositeT, p, vec4(transmittance, 1.0));
    }
#else
    vec4 c = imageLoad(engineColor, p);
    c.rgb = addOnly ? c.rgb + exposed : c.rgb * transmittance + exposed;
    imageStore(engineColor, p, c);
#endif
#if LS_WITH_OUTPUT
    vec3 earlier = addOnly ? imageLoad(inscatterOut, p).rgb : vec3(0.0);
    imageStore(inscatterOut, p, vec4(earlier + lin, 1.0));
#endif
}

// The camera ray's transmittance to S: exp(-betaT S), or of its optical depth in a non-uniform
// medium (the pixel's ray).
vec3 pixelTransmittance(ivec2 p, float S) {
    if (kMedia == 0) return exp(-frame.betaT.rgb * S);
    return exp(-frame.betaT.rgb * opticalDepth(frame.cameraPos.xyz, pixelRayDirection(p), S));
}

// The pixel keeps what its color and Lin output hold (an invocation that returns early): nothing
// to do for a storage image, the blend's identity for an attachment.
void compositeKeep() {
#if defined(LS_BLEND) && LS_BLEND
    compositeLin = vec4(0.0);
    compositeTransmittance = vec4(1.0);
#endif
}

void compositeInto(ivec2 p, vec3 lin, float S, bool addOnly) {
    compositeWith(p, lin, addOnly ? vec3(1.0) : pixelTransmittance(p, S), addOnly);
}

#endif
