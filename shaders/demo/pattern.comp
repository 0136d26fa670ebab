#version 450
#extension GL_GOOGLE_include_directive : require
#include "pattern.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform writeonly image2D outPattern;

void main() {
    uvec2 size = uvec2(imageSize(outPattern));
    uvec2 p = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(p, size))) return;
    imageStore(outPattern, ivec2(p), testPattern(p, size));
}
