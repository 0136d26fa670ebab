#version 450
#extension GL_GOOGLE_include_directive : require
// Brute force (seed 000's starting point): every pixel marches its own ray through every shadow-map
// texel it crosses. The on-GPU reference the other methods are compared with.
#include "camera.glsl"
layout(binding = 1) uniform sampler2D cameraZ;
layout(binding = 6) uniform sampler2D shadowMap;
#if LS_NEEDS_TABLE
layout(binding = 7) uniform sampler2D pointTable;
#endif
#if LS_LIGHT_COLOR
layout(binding = 8) uniform sampler2D lightColorMap;
#endif
#include "march.glsl"
layout(push_constant) uniform Push { uint maxSteps; } pc;
layout(location = 0) out vec4 outInscatter;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 v = rayDirection(pixelToNdc(vec2(pixel) + 0.5));
    float S = texelFetch(cameraZ, pixel, 0).r / max(dot(v, frame.cameraForward.xyz), 1e-4);
    outInscatter = vec4(marchRay(frame.cameraPos.xyz, v, S, pc.maxSteps), 1.0);
}
