#version 450
#extension GL_GOOGLE_include_directive : require
// Seed 000's starting point: a pixel marches its own ray through every shadow-map texel it
// crosses. Brute force runs it on every pixel (the on-GPU reference the other methods are compared
// with); the epipolar fix-up on the pixels its unwarp could not serve, with an optional step cap.
#include "camera.glsl"
layout(binding = 1) uniform sampler2D depthBuffer;  // the engine's depth
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
layout(binding = 6) uniform sampler2DArray shadowMap;  // a point light's six cube faces
#else
layout(binding = 6) uniform sampler2D shadowMap;
#endif
#if LS_NEEDS_TABLE
layout(binding = 7) uniform sampler2D pointTable;
#endif
#if LS_LIGHT_COLOR
layout(binding = 8) uniform sampler2D lightColorMap;
#endif
#include "march.glsl"
layout(push_constant) uniform Push { uint maxSteps; } pc;  // 0: one step per texel
layout(location = 0) out vec4 outInscatter;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 v = pixelRayDirection(pixel);
    float S = rayLength(pixelCameraZ(depthBuffer, pixel), v);
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
    outInscatter = vec4(marchRayCube(frame.cameraPos.xyz, v, S, pc.maxSteps), 1.0);
#else
    outInscatter = vec4(marchRay(frame.cameraPos.xyz, v, S, pc.maxSteps), 1.0);
#endif
}
