#version 450
#extension GL_GOOGLE_include_directive : require
// FrameDescription::transmittanceOut: the split composite's transmittance (composite_into.glsl's
// LS_SPLIT) copied into the engine's image (R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT,
// LS_OUT_RGBA32F), T per channel in rgb and 1 in alpha, over the frame's pixels only.
#include "bindings.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = LS_BINDING_SPLIT_T) uniform sampler2D splitT;
#if LS_OUT_RGBA32F
layout(binding = LS_BINDING_SPLIT_TARGET, rgba32f) uniform writeonly image2D transmittanceOut;
#else
layout(binding = LS_BINDING_SPLIT_TARGET, rgba16f) uniform writeonly image2D transmittanceOut;
#endif
layout(push_constant) uniform Push {
    ivec2 size;  // the frame's extent
} pc;

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, pc.size))) return;
    imageStore(transmittanceOut, p, vec4(texelFetch(splitT, p, 0).rgb, 1.0));
}
