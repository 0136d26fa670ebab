#version 450
#extension GL_GOOGLE_include_directive : require
// The split composite (composite_into.glsl's LS_SPLIT) blended into the engine's color as a color
// attachment, which any format a device can blend into takes (B10G11R11, A2B10G10R10, 8-bit UNORM
// and sRGB, float targets without STORAGE): color = color * T + k Lin. With dual-source blending
// one draw does it (src0 + dst * src1); without, two draws of this shader, the first multiplying by
// T, the second adding k Lin. The blend runs in the attachment's own arithmetic: an sRGB target is
// blended in linear, a UNORM one clamps to [0, 1].
#include "bindings.h"
layout(binding = LS_BINDING_SPLIT_LIN) uniform sampler2D splitLin;  // k Lin
layout(binding = LS_BINDING_SPLIT_T) uniform sampler2D splitT;      // the transmittance
#if LS_DUAL_SOURCE
layout(location = 0, index = 0) out vec4 lin;
layout(location = 0, index = 1) out vec4 transmittance;
#else
layout(location = 0) out vec4 outColor;
layout(push_constant) uniform Push {
    uint addLin;  // 0: the draw that multiplies by T; 1: the draw that adds k Lin
} pc;
#endif

void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
#if LS_DUAL_SOURCE
    lin = vec4(texelFetch(splitLin, p, 0).rgb, 0.0);
    transmittance = vec4(texelFetch(splitT, p, 0).rgb, 1.0);
#else
    outColor = pc.addLin != 0u ? vec4(texelFetch(splitLin, p, 0).rgb, 0.0)
                               : vec4(texelFetch(splitT, p, 0).rgb, 1.0);
#endif
}
