#version 450
#extension GL_GOOGLE_include_directive : require
// The temporal mode's blue-noise tile (passes/froxels/froxel_blue_noise.cpp makes it on the CPU):
// copied from the buffer the frame uploaded into the image the frame graph keeps, once.
#include "froxel_bindings.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = LS_BINDING_FROXEL_NOISE_TEXELS, std430) readonly buffer Texels {
    float texels[];
};
layout(binding = LS_BINDING_FROXEL_NOISE_OUT, r32f) uniform writeonly image2D noiseOut;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy), size = imageSize(noiseOut);
    if (any(greaterThanEqual(p, size))) return;
    imageStore(noiseOut, p, vec4(texels[p.y * size.x + p.x], 0.0, 0.0, 0.0));
}
