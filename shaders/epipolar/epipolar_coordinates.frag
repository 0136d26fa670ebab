#version 450
#extension GL_GOOGLE_include_directive : require
// One fragment per epipolar sample (x: sample, y: slice): its screen position (NDC mapped to [0, 1])
// and camera-space z.
// Samples off the screen or on culled slices are discarded, so only valid ones reach the stencil.
#include "epipolar_geometry.glsl"
#include "camera.glsl"
#include "epipolar_bindings.h"
layout(binding = LS_BINDING_COORDINATES_END_POINTS) uniform sampler2D sliceEndPoints;
layout(binding = LS_BINDING_COORDINATES_DEPTH) uniform sampler2D depthBuffer;  // the engine's depth
layout(location = 0) out vec2 outCoordinate;
layout(location = 1) out float outCameraZ;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 ends = texelFetch(sliceEndPoints, ivec2(p.y, 0), 0);
    if (ends.x <= INVALID_SLICE + 1.0) discard;
    float t = float(p.x) / max(epipolar.sampling.y - 1.0, 1.0);
    vec2 pos = mix(ends.xy, ends.zw, t);
    if (!insideBoundary(pos, 1e-5)) discard;
    ivec2 pixel = clamp(ivec2(floor(ndcToPixel(pos))), ivec2(0), ivec2(frame.screenSize.xy) - 1);
    outCoordinate = pos * 0.5 + 0.5;  // [0, 1]: stored as unorm16 where the device has it
    outCameraZ = pixelCameraZ(depthBuffer, pixel);
}
