#version 450
#extension GL_GOOGLE_include_directive : require
// Lights without a shadow map: Lin in closed form per pixel (Hoffman-Preetham for a directional
// light, the seed's table for point and spot lights, the spot clipped to its cone and range).
#include "camera.glsl"
layout(binding = LS_BINDING_DEPTH) uniform sampler2D depthBuffer;  // the engine's depth
#if LS_NEEDS_TABLE
layout(binding = LS_BINDING_POINT_TABLE) uniform sampler2D pointTable;
#endif
#include "integrate.glsl"
#include "light_volume.glsl"
layout(location = 0) out vec4 outInscatter;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 C = frame.cameraPos.xyz;
    vec3 v = pixelRayDirection(pixel);
    float S = rayLength(pixelCameraZ(depthBuffer, pixel), v);
    float t0, t1;
    lightInterval(C, v, S, t0, t1);
    vec3 lin = vec3(0.0);
    if (t0 < t1) {
        Inscatter acc = beginInscatter(C, v, t0);
        advance(acc, t1, vec3(1.0));
        lin = finishInscatter(acc, v);
    }
    outInscatter = vec4(storedLin(lin), 1.0);
}
