#version 450
// Several lights: one more light's Lin added into the engine's color (the first light's composite
// applied the extinction) and, optionally, into the Lin output image, which then holds the sum.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D inscatter;
#if LS_COLOR_RGBA32F
layout(binding = 1, rgba32f) uniform image2D color;
#else
layout(binding = 1, rgba16f) uniform image2D color;
#endif
#if LS_WITH_OUTPUT
layout(binding = 2, rgba32f) uniform image2D inscatterOut;
#endif

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(color)))) return;
    vec3 lin = texelFetch(inscatter, p, 0).rgb;
    vec4 c = imageLoad(color, p);
    c.rgb += lin;
    imageStore(color, p, c);
#if LS_WITH_OUTPUT
    imageStore(inscatterOut, p, vec4(imageLoad(inscatterOut, p).rgb + lin, 1.0));
#endif
}
