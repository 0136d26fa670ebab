#version 450
#extension GL_GOOGLE_include_directive : require
// Refinement on in-scattering differences, after the first march. Drawn over every sample: a valid
// interpolated sample whose two sources differ becomes its own source, so that the refinement's
// marking (mark_ray_march.frag, into the march's stencil where the first march's samples are not)
// gives it to the second march, and only it; any other sample is left as it is.
// A sample reads and writes its own texel of the sources only, so rewriting them in place is safe.
// The whole run between two differing sources is marched (not a halved step, recursively): one
// extra march instead of log2(initial step) mark-and-march rounds, and every sample of the run
// then reads its own value, so the edge is where the march puts it.
#include "epipolar_constants.glsl"
#include "frame.glsl"
#include "epipolar_bindings.h"
layout(binding = LS_BINDING_REFINE_MARCHED) uniform sampler2D marched;
layout(binding = LS_BINDING_REFINE_LIN_SOURCES, rg16ui) uniform uimage2D interpolationSource;
layout(binding = LS_BINDING_SOURCES_EPIPOLAR_Z) uniform sampler2D epipolarZ;

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
    if (!validSampleZ(texelFetch(epipolarZ, p, 0).r)) return;
    uvec2 src = imageLoad(interpolationSource, p).xy;
    uint k = uint(p.x);
    if (src.x == k && src.y == k) return;  // marched already
    // The marched samples are in the march's order.
    vec4 a = texelFetch(marched, marchTexel(int(src.x), p.y), 0);
    vec4 b = texelFetch(marched, marchTexel(int(src.y), p.y), 0);
    if (differ(a, b, epipolar.marching.z)) imageStore(interpolationSource, p, uvec4(k, k, 0u, 0u));
}
