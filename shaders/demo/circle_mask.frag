#version 450
#extension GL_GOOGLE_include_directive : require
#include "pattern.glsl"
// Writes nothing but stencil: fragments outside the circle are discarded, the pipeline's stencil
// op replaces the rest with the reference value.
layout(push_constant) uniform Push { uvec2 size; } pc;

void main() {
    if (!insideCircle(uvec2(gl_FragCoord.xy), pc.size)) discard;
}
