#version 450
#extension GL_GOOGLE_include_directive : require
#include "epipolar_bindings.h"
// Passes (and so increments the stencil of) the samples that are their own interpolation source:
// the ray-marching samples.
layout(binding = LS_BINDING_INTERPOLATION_SOURCE) uniform usampler2D interpolationSource;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    uvec2 src = texelFetch(interpolationSource, p, 0).xy;
    if (src.x != uint(p.x) || src.y != uint(p.x)) discard;
}
