#version 450
#extension GL_GOOGLE_include_directive : require
// The froxel grid applied per pixel: Lin and the transmittance from the camera to the pixel's
// camera-space z, by a trilinear fetch of the integrated grid, composited into the engine's color
// with the grid's transmittance (as engines do; docs/methods.md gives how far it is from
// exp(-betaT S)). Froxel k holds the integral to slice k + 1's start, so z at slice coordinate u
// reads the grid at depth (u - 0.5) / slices; within the first slice it blends from the camera's
// (0, 1).
// Beyond the far distance the grid's last froxel holds.
#include "froxel_grid.glsl"
#include "composite_into.glsl"
#include "froxel_bindings.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = LS_BINDING_DEPTH) uniform sampler2D depthBuffer;  // the engine's depth
layout(binding = LS_BINDING_FROXEL_INTEGRATED) uniform sampler3D integrated;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    // The frame's extent, not the image's: under dynamic resolution the engine's images are larger
    // than the frame, and what lies outside it is the engine's.
    if (any(greaterThanEqual(p, ivec2(frame.screenSize.xy)))) return;
    float z = pixelCameraZ(depthBuffer, p);
    float u = clamp(sliceCoordinate(z), 0.0, pc.grid.z);
    vec2 xy = (vec2(p) + 0.5) / (pc.grid.xy * pc.grid.w);
    // Under dynamic resolution the grid has columns and rows beyond the frame's: the frame's last
    // half column reads its own last column alone, as the edge of a grid of the frame's size would
    // (the clamp binds only then, so a grid of the frame's size reads what it always read).
    const vec2 used = ceil(frame.screenSize.xy / pc.grid.w);
    xy = mix(xy, min(xy, (used - 0.5) / pc.grid.xy), lessThan(used, pc.grid.xy));
    vec4 g = textureLod(integrated, vec3(xy, (max(u, 1.0) - 0.5) / pc.grid.z), 0.0);
    // The first slice starts at the camera (the integration's): linear in z from there.
    if (u < 1.0) g = mix(vec4(0.0, 0.0, 0.0, 1.0), g, clamp(z / sliceZ(1.0), 0.0, 1.0));
    vec3 lin = max(g.rgb, vec3(0.0)) / pc.slices.w;
    compositeWith(p, lin, vec3(g.a), false);
}
