#version 450
#extension GL_GOOGLE_include_directive : require
// Refinement on in-scattering differences, after the first march. Drawn over every valid sample
// (stencil != 0, incremented where the fragment is kept):
// - a sample marched already (its own source, stencil 2) is kept, so it leaves for 3 and the
//   second march (stencil 2) skips it;
// - an interpolated sample (stencil 1) whose two sources differ becomes its own source and is kept
//   (stencil 2): the second march marches it, and only it;
// - any other sample is discarded and stays interpolated.
// A sample reads and writes its own texel of the sources only, so rewriting them in place is safe.
// The whole run between two differing sources is marched (not a halved step, recursively): one
// extra march instead of log2(initial step) mark-and-march rounds, and every sample of the run
// then reads its own value, so the edge is where the march puts it.
#include "epipolar_constants.glsl"
#include "frame.glsl"
#include "epipolar_bindings.h"
layout(binding = LS_BINDING_REFINE_MARCHED) uniform sampler2D marched;
layout(binding = LS_BINDING_REFINE_LIN_SOURCES, rg16ui) uniform uimage2D interpolationSource;

// Per channel, relative to the larger of the two: a shadow edge changes every channel of the
// shadowed fraction alike, a light-color texture can change one alone. A source that carries no
// light (alpha 0, outside a spot's cone) against one that does is a difference too.
bool differ(vec4 a, vec4 b, float threshold) {
    if ((a.a > 0.0) != (b.a > 0.0)) return true;
    if (a.a <= 0.0) return false;
    vec3 d = abs(a.rgb - b.rgb);
    vec3 m = max(abs(a.rgb), abs(b.rgb));
    return any(greaterThan(d, threshold * m));
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    uvec2 src = imageLoad(interpolationSource, p).xy;
    if (src.x == uint(p.x) && src.y == uint(p.x)) return;  // marched already: 2 -> 3
    vec4 a = texelFetch(marched, ivec2(src.x, p.y), 0);
    vec4 b = texelFetch(marched, ivec2(src.y, p.y), 0);
    if (!differ(a, b, epipolar.marching.z)) discard;
    imageStore(interpolationSource, p, uvec4(uint(p.x), uint(p.x), 0u, 0u));  // 1 -> 2
}
