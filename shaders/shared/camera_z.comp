#version 450
#extension GL_GOOGLE_include_directive : require
// Camera-space z of every pixel's ray end (surface or sky), from the engine's depth buffer.
#include "camera.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 1) uniform sampler2D depthBuffer;
layout(binding = 2, r32f) uniform writeonly image2D cameraZ;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(cameraZ)))) return;
    float depth = texelFetch(depthBuffer, p, 0).r;
    vec3 v = pixelRayDirection(p);
    imageStore(cameraZ, p, vec4(rayEndCameraZ(depth, dot(v, frame.cameraForward.xyz))));
}
