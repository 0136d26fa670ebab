#version 450
// A debug pass whose output nobody reads: the compiler culls it.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;
layout(binding = 1, r32f) uniform writeonly image2D outLuma;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(outLuma)))) return;
    vec3 c = texelFetch(source, p, 0).rgb;
    imageStore(outLuma, p, vec4(dot(c, vec3(0.2126, 0.7152, 0.0722))));
}
