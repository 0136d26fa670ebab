// The composite, done where Lin is made: color = color * exp(-betaT S) + k Lin in the engine's
// image (k the engine's pre-exposure, 1 by default), and Lin alone, unexposed, into the output
// image when the frame asked for one. A frame's later lights
// (addOnly) add their Lin to both: the first light's composite applied the extinction. Each
// invocation touches its own pixel only. The engine color's format and the output image are
// build-time variants (LS_COLOR_RGBA32F, LS_WITH_OUTPUT): a storage image read needs its format.
#ifndef LS_COMPOSITE_INTO_GLSL
#define LS_COMPOSITE_INTO_GLSL
#include "frame.glsl"

#if LS_COLOR_RGBA32F
layout(binding = LS_BINDING_ENGINE_COLOR, rgba32f) uniform image2D engineColor;
#else
layout(binding = LS_BINDING_ENGINE_COLOR, rgba16f) uniform image2D engineColor;
#endif
#if LS_WITH_OUTPUT
layout(binding = LS_BINDING_LIN_OUT, rgba32f) uniform image2D inscatterOut;
#endif

// With the transmittance given: color = color * transmittance + k Lin (froxels' grid holds it).
void compositeWith(ivec2 p, vec3 lin, vec3 transmittance, bool addOnly) {
    vec4 c = imageLoad(engineColor, p);
    const vec3 exposed = lin * frame.linStorage.z;
    c.rgb = addOnly ? c.rgb + exposed : c.rgb * transmittance + exposed;
    imageStore(engineColor, p, c);
#if LS_WITH_OUTPUT
    vec3 earlier = addOnly ? imageLoad(inscatterOut, p).rgb : vec3(0.0);
    imageStore(inscatterOut, p, vec4(earlier + lin, 1.0));
#endif
}

void compositeInto(ivec2 p, vec3 lin, float S, bool addOnly) {
    compositeWith(p, lin, addOnly ? vec3(1.0) : exp(-frame.betaT.rgb * S), addOnly);
}

#endif
