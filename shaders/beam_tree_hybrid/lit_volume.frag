#version 450
#extension GL_GOOGLE_include_directive : require
// Seed 004's volume-based integration (3.2.2) over the fully lit pyramids: a face where the pixel's
// ray leaves the lit volume adds E(0, z), one where it enters subtracts it, E being the model's
// unshadowed in-scattering from the camera to distance z (the point-light table in closed form,
// limited to the spot's cone and range). z is clamped to the ray's end S, so scene surfaces cut
// the lit intervals wherever they are; a float target holds the negative partial sums, so seed
// 004's numOverflow is not needed. A camera inside the lit volume sees only exits: E(0, b).
// With kSimplifiedModel, E is seed 004's own closed form (2.17) of its simplified light model.
#include "bindings.h"
layout(binding = LS_BINDING_POINT_TABLE) uniform sampler2D pointTable;
#include "camera.glsl"
#include "integrate.glsl"
#include "light_volume.glsl"
#include "simplified.glsl"
layout(binding = LS_BINDING_DEPTH) uniform sampler2D depthBuffer;  // the engine's depth

layout(location = 0) in vec3 fromCamera;
layout(location = 1) flat in int plane;
layout(location = 0) out vec4 outLin;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 C = frame.cameraPos.xyz;
    vec3 v = pixelRayDirection(pixel);
    float S = rayLength(pixelCameraZ(depthBuffer, pixel), v);
    float z = min(dot(fromCamera, v), S);
    float t0, t1;
    lightInterval(C, v, S, t0, t1);
    vec3 E = vec3(0.0);
    if (z > t0 && t0 < t1)
        E = kSimplifiedModel ? simplifiedInscatter(C, v, t0, min(z, t1))
                             : unshadowedInscatter(C, v, t0, min(z, t1));
    // Triangles are wound counter-clockwise seen from outside: a front face is an entry.
    outLin = vec4(storedLin(gl_FrontFacing ? -E : E), 0.0);
}
