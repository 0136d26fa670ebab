#version 450
#extension GL_GOOGLE_include_directive : require
// World-space triangles the CPU made this frame (seed 004: the lit pyramids' surfaces, or the
// uncertain parts of sampling planes), pulled from a storage buffer (the draw's first vertex says where).
#include "frame.glsl"
#include "beam_tree_bindings.h"

layout(std430, binding = LS_BINDING_BEAM_TRIANGLES) readonly buffer Triangles { vec4 points[]; };
// The lit pyramids (drawn without a depth test): clipped by the sides of the view only. Their faces
// reach past the far plane (a point light's backplate cube encloses every view ray's end, at
// |L - C| + twice the view's reach), and a face clipped there would drop its E(0, S) from every
// pixel behind it; a depth of half the clip range keeps them, and the side planes still cut away
// whatever lies behind the camera.
layout(constant_id = LS_SPEC_UNCLIPPED_DEPTH) const bool kUnclippedDepth = false;
// From the camera, as planes.vert gives its points to planes.frag, which draws these triangles too.
layout(location = 0) out vec3 fromCamera;
layout(location = 1) flat out int plane;

void main() {
    vec3 worldPos = points[gl_VertexIndex].xyz;
    fromCamera = worldPos - frame.cameraPos.xyz;
    plane = 0;
    gl_Position = frame.viewProj * vec4(worldPos, 1.0);
    if (kUnclippedDepth) gl_Position.z = 0.5 * gl_Position.w;
}
