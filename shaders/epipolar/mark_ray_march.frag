#version 450
#extension GL_GOOGLE_include_directive : require
// Marks the ray-marching samples (valid ones that are their own interpolation source) in the
// march's stencil, in the march's order (marchTexel): each fragment reads its sample where the
// other textures keep it. With the march list (marchesFromList), a texel of the tiles is marked
// where its slot holds a sample, the first `count` of them (unless the list overflowed). Every
// other fragment is discarded. With the list, the pass draws only the texels that can be marked
// (march_cover.vert).
#include "epipolar_constants.glsl"
#include "epipolar_bindings.h"
layout(binding = LS_BINDING_INTERPOLATION_SOURCE) uniform usampler2D interpolationSource;
layout(binding = LS_BINDING_SOURCES_EPIPOLAR_Z) uniform sampler2D epipolarZ;
layout(std430, binding = LS_BINDING_MARCH_LIST) readonly buffer MarchList {
    uint count;
} marchList;

void main() {
    ivec2 at;
    int slot = marchListSlot(ivec2(gl_FragCoord.xy), marchList.count, at);
    if (slot >= 0) {
        if (uint(slot) >= marchList.count) discard;
        return;
    }
    uint k = uint(at.x);
    uvec2 src = texelFetch(interpolationSource, at, 0).xy;
    if (!validSampleZ(texelFetch(epipolarZ, at, 0).r) || src.x != k || src.y != k) discard;
}
