#version 450
// Reads texel (1, 1) of each of the six layers of a 2D-array depth image.
layout(local_size_x = 6) in;
layout(binding = 0) uniform sampler2DArray layers;
layout(binding = 1) writeonly buffer Out { float values[]; };

void main() {
    uint i = gl_LocalInvocationID.x;
    values[i] = texelFetch(layers, ivec3(1, 1, int(i)), 0).r;
}
