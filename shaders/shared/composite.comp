#version 450
#extension GL_GOOGLE_include_directive : require
// color = color * exp(-betaT S) + Lin (seed 000's aerial perspective), in the engine's image, and
// optionally Lin alone into an output image. Nothing else: no tone mapping, no exposure.
#include "camera.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 1) uniform sampler2D depthBuffer;  // the engine's depth
#if LS_COLOR_RGBA32F
layout(binding = 2, rgba32f) uniform image2D color;
#else
layout(binding = 2, rgba16f) uniform image2D color;
#endif
#if LS_WITH_LIN
layout(binding = 3) uniform sampler2D inscatter;
#endif
#if LS_WITH_OUTPUT
layout(binding = 4, rgba32f) uniform writeonly image2D inscatterOut;
#endif

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(color)))) return;
    vec3 v = pixelRayDirection(p);
    float S = rayLength(pixelCameraZ(depthBuffer, p), v);
#if LS_WITH_LIN
    vec3 lin = texelFetch(inscatter, p, 0).rgb;
#else
    vec3 lin = vec3(0.0);
#endif
    vec4 c = imageLoad(color, p);
    c.rgb = c.rgb * exp(-frame.betaT.rgb * S) + lin;
    imageStore(color, p, c);
#if LS_WITH_OUTPUT
    imageStore(inscatterOut, p, vec4(lin, 1.0));
#endif
}
