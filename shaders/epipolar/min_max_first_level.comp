#version 450
#extension GL_GOOGLE_include_directive : require
// First level of every slice's min/max tree, from the shadow map: each node covers two samples
// along the slice's line and keeps the min and max of every texel their filtering can read, so the
// accelerated march decides exactly as visiting every texel would.
#include "min_max_tree.glsl"
#include "epipolar_constants.glsl"
#include "frame.glsl"
#include "epipolar_bindings.h"
layout(local_size_x = 64) in;
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
layout(binding = LS_BINDING_TREE_SHADOW_MAP) uniform sampler2DArray shadowMap;  // a point light's cube: the face epipolar.cubeFace.x
#else
layout(binding = LS_BINDING_TREE_SHADOW_MAP) uniform sampler2D shadowMap;
#endif
layout(binding = LS_BINDING_TREE_UV_FRAME) uniform sampler2D sliceUvFrame;
layout(binding = LS_BINDING_TREE_FIRST_LEVEL, rg16f) uniform writeonly image2D level1;
#include "shadow.glsl"

void main() {
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
    shadowFace = int(epipolar.cubeFace.x);
#endif
    int node = int(gl_GlobalInvocationID.x);
    int slice = int(gl_GlobalInvocationID.y);
    int n = int(frame.shadowInfo.x);
    if (node >= (n >> 1)) return;
    vec4 f = texelFetch(sliceUvFrame, ivec2(slice, 0), 0);
    vec2 mm = vec2(0.0, 1.0);  // a slice without a frame never decides from its tree
    if (dot(f.zw, f.zw) > 0.0) {
        vec2 a = shadowFootprintMinMax(f.xy + float(2 * node) * f.zw);
        vec2 b = shadowFootprintMinMax(f.xy + float(2 * node + 1) * f.zw);
        mm = vec2(min(a.x, b.x), max(a.y, b.y));
    }
    imageStore(level1, ivec2(treeLevelOffset(1, n) + node, slice), vec4(encodeTreeNode(mm), 0.0, 0.0));
}
