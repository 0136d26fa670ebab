#version 450
#extension GL_GOOGLE_include_directive : require
// Entry and exit point of every slice's epipolar line (NDC), with the seed's optimised placement:
// exit points on the shrunk boundary, lines off screen culled, and lines shorter than one pixel per
// sample stretched so that samples fall 1:1 on pixels (those past the screen are not valid).
#include "epipolar_geometry.glsl"
#include "epipolar_bindings.h"
layout(local_size_x = 64) in;
layout(binding = LS_BINDING_SLICE_END_POINTS_OUT, rgba32f) uniform writeonly image2D sliceEndPoints;

void main() {
    int slice = int(gl_GlobalInvocationID.x);
    if (slice >= int(epipolar.sampling.x)) return;
    int edge;
    vec2 exitPoint = sliceExitPoint(slice, edge);
    vec2 light = frame.lightScreen.xy;
    vec2 entry = light;
    // The light (or, behind the camera, the point its shafts converge to) may be off screen: the line
    // from it must then cross the screen and leave through this slice's edge.
    if (!insideBoundary(light, 0.0)) {
        vec2 d = exitPoint - light;
        float tNear, tFar;
        int farEdge;
        boundaryRange(light, d, tNear, tFar, farEdge);
        if (dot(d, edgeOutwardNormal(edge)) <= 0.0 || tNear >= tFar || tNear >= 1.0 - 1e-6) {
            imageStore(sliceEndPoints, ivec2(slice, 0), vec4(INVALID_SLICE));
            return;
        }
        entry = light + max(tNear, 0.0) * d;
    }
    float samples = epipolar.sampling.y;
    float pixels = length((exitPoint - entry) * frame.screenSize.xy * 0.5);
    float stretch = max((samples - 1.0) / max(pixels, 1e-3), 1.0);
    exitPoint = entry + (exitPoint - entry) * stretch;
    imageStore(sliceEndPoints, ivec2(slice, 0), vec4(entry, exitPoint));
}
