#version 450
// 3x3 box filter with clamp-to-edge, then quantised to the 8-bit output.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;
layout(binding = 1, rgba8) uniform writeonly image2D outImage;

void main() {
    ivec2 size = imageSize(outImage);
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, size))) return;
    vec4 sum = vec4(0.0);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            sum += texelFetch(source, clamp(p + ivec2(dx, dy), ivec2(0), size - 1), 0);
    imageStore(outImage, p, sum / 9.0);
}
