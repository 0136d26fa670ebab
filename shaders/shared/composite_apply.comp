#version 450
#extension GL_GOOGLE_include_directive : require
// The split composite (composite_into.glsl's LS_SPLIT) applied to an engine color that is a
// storage image (R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT, LS_COLOR_RGBA32F) when the frame split
// it for its transmittance output: color = color * T + k Lin, over the frame's pixels only.
#include "bindings.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = LS_BINDING_SPLIT_LIN) uniform sampler2D splitLin;
layout(binding = LS_BINDING_SPLIT_T) uniform sampler2D splitT;
#if LS_COLOR_RGBA32F
layout(binding = LS_BINDING_SPLIT_TARGET, rgba32f) uniform image2D engineColor;
#else
layout(binding = LS_BINDING_SPLIT_TARGET, rgba16f) uniform image2D engineColor;
#endif
layout(push_constant) uniform Push {
    ivec2 size;  // the frame's extent (the image may be larger: dynamic resolution)
} pc;

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, pc.size))) return;
    vec4 c = imageLoad(engineColor, p);
    c.rgb = c.rgb * texelFetch(splitT, p, 0).rgb + texelFetch(splitLin, p, 0).rgb;
    imageStore(engineColor, p, c);
}
