#version 450
#extension GL_GOOGLE_include_directive : require
// Origin and direction of each slice in shadow-map UV (seed 000's "universal" construction, for any
// camera, inside or outside a spot's cone, or a directional light). Every camera ray of a slice lies
// in the plane through the camera and the light, which projects onto one line of the shadow map,
// and all of them travel along it the same way. In light clip space a ray is Xc + d Xv; its
// projected direction is Xv.xy Xc.w - Xc.xy Xv.w at every d, the same up to a positive factor for
// every ray of the slice. The origin is where that line enters the [0,1]^2 square; the direction is
// scaled to one texel per step along its major axis. (0,0,0,0) marks a slice that misses the map.
// With LS_CUBE_SHADOW the maps are the six faces of a point light's cube, each a spot light's map:
// one row per face (gl_GlobalInvocationID.y), a face out of view left without lines.
#include "epipolar_geometry.glsl"
#include "camera.glsl"
#include "epipolar_bindings.h"
layout(local_size_x = 64) in;
layout(binding = LS_BINDING_UV_FRAME_END_POINTS) uniform sampler2D sliceEndPoints;
layout(binding = LS_BINDING_UV_FRAME_OUT, rgba32f) uniform writeonly image2D sliceUvFrame;

void main() {
    int slice = int(gl_GlobalInvocationID.x);
    int face = int(gl_GlobalInvocationID.y);
    if (slice >= int(epipolar.sampling.x)) return;
    vec4 ends = texelFetch(sliceEndPoints, ivec2(slice, 0), 0);
    if (ends.x <= INVALID_SLICE + 1.0 || !cubeFaceReachesView(face)) {
        imageStore(sliceUvFrame, ivec2(slice, face), vec4(0.0));
        return;
    }
    vec3 C = frame.cameraPos.xyz;
    vec3 v = rayDirection(ends.zw);
    vec4 Xc = shadowViewProj(face) * vec4(C, 1.0);
    vec4 Xv = shadowViewProj(face) * vec4(v, 0.0);
    vec2 dir = Xv.xy * Xc.w - Xc.xy * Xv.w;  // clip xy; uv = xy / 2 + 1/2 keeps its sign
    float size = frame.shadowInfo.x;
    if (dot(dir, dir) < 1e-24) dir = vec2(1.0, 0.0);  // the slice projects to a point
    dir = dir / max(abs(dir.x), abs(dir.y)) / size;
    // A point of the line: the projection of any point of the slice plane off the light's plane.
    vec4 X = abs(Xc.w) > 1e-6 ? Xc : Xc + Xv;
    vec2 p0 = X.xy / X.w * 0.5 + 0.5;
    vec2 inv = 1.0 / mix(dir, vec2(1e-20), lessThan(abs(dir), vec2(1e-20)));
    vec2 ta = (vec2(0.0) - p0) * inv, tb = (vec2(1.0) - p0) * inv;
    float tNear = max(min(ta.x, tb.x), min(ta.y, tb.y));
    float tFar = min(max(ta.x, tb.x), max(ta.y, tb.y));
    if (tNear > tFar) {
        imageStore(sliceUvFrame, ivec2(slice, face), vec4(0.0));
        return;
    }
    imageStore(sliceUvFrame, ivec2(slice, face), vec4(p0 + tNear * dir, dir));
}
