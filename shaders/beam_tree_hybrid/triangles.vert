#version 450
#extension GL_GOOGLE_include_directive : require
// World-space triangles the CPU made this frame (seed 004: the lit pyramids' surfaces, or the
// uncertain parts of sampling planes), pulled from a storage buffer (the draw's first vertex says where).
#include "frame.glsl"

layout(std430, binding = 3) readonly buffer Triangles { vec4 points[]; };
layout(location = 0) out vec3 worldPos;
layout(location = 1) flat out int plane;

void main() {
    worldPos = points[gl_VertexIndex].xyz;
    plane = 0;
    gl_Position = frame.viewProj * vec4(worldPos, 1.0);
}
