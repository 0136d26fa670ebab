#version 450
#extension GL_GOOGLE_include_directive : require
#include "epipolar_constants.glsl"
#include "epipolar_bindings.h"
// In-scattering (or shadowed fraction) of every valid sample, linearly interpolated between its two
// ray-marching sources; the others keep the clear value.
layout(binding = LS_BINDING_INTERPOLATION_SOURCE) uniform usampler2D interpolationSource;
layout(binding = LS_BINDING_INTERPOLATE_MARCHED) uniform sampler2D marched;
layout(binding = LS_BINDING_SOURCES_EPIPOLAR_Z) uniform sampler2D epipolarZ;
layout(location = 0) out vec4 outInscatter;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (!validSampleZ(texelFetch(epipolarZ, p, 0).r)) discard;  // stays cleared
    uvec2 src = texelFetch(interpolationSource, p, 0).xy;
    // The marched samples are in the march's order.
    vec4 a = texelFetch(marched, marchTexel(int(src.x), p.y), 0);
    vec4 b = texelFetch(marched, marchTexel(int(src.y), p.y), 0);
    float t = src.y > src.x ? (float(p.x) - float(src.x)) / float(src.y - src.x) : 0.0;
    // Alpha says whether a source's value means anything (see ray_march.frag); an undefined source
    // gives way to the other one.
    float wa = (1.0 - t) * a.a, wb = t * b.a;
    vec3 rgb = wa + wb > 0.0 ? (a.rgb * wa + b.rgb * wb) / (wa + wb) : vec3(0.0);
    outInscatter = vec4(rgb, mix(a.a, b.a, t));
}
