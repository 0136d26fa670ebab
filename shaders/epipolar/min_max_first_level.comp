#version 450
#extension GL_GOOGLE_include_directive : require
// First level of every slice's min/max tree, from the shadow map: each node covers two samples
// along the slice's line and keeps the min and max of every texel their filtering can read, so the
// accelerated march decides exactly as visiting every texel would. With LS_CUBE_SHADOW the six
// faces of a point light's cube at once: face gl_GlobalInvocationID.z's trees in its array layer.
#include "min_max_tree.glsl"
#include "epipolar_constants.glsl"
#include "frame.glsl"
#include "epipolar_bindings.h"
layout(local_size_x = 64) in;
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
layout(binding = LS_BINDING_TREE_SHADOW_MAP) uniform sampler2DArray shadowMap;
layout(binding = LS_BINDING_TREE_FIRST_LEVEL, rg16f) uniform writeonly image2DArray level1;
void storeNode(ivec2 p, int face, vec2 v) { imageStore(level1, ivec3(p, face), vec4(v, 0.0, 0.0)); }
#else
layout(binding = LS_BINDING_TREE_SHADOW_MAP) uniform sampler2D shadowMap;
layout(binding = LS_BINDING_TREE_FIRST_LEVEL, rg16f) uniform writeonly image2D level1;
void storeNode(ivec2 p, int face, vec2 v) { imageStore(level1, p, vec4(v, 0.0, 0.0)); }
#endif
layout(binding = LS_BINDING_TREE_UV_FRAME) uniform sampler2D sliceUvFrame;
#include "shadow.glsl"

void main() {
    int node = int(gl_GlobalInvocationID.x);
    int slice = int(gl_GlobalInvocationID.y);
    int face = int(gl_GlobalInvocationID.z);
    int n = int(frame.shadowInfo.x);
    // A face out of view: no ray marches its lines, nothing reads its trees.
    if (node >= (n >> 1) || !cubeFaceReachesView(face)) return;
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
    shadowFace = face;
#endif
    vec4 f = texelFetch(sliceUvFrame, ivec2(slice, face), 0);
    vec2 mm = vec2(0.0, 1.0);  // a slice without a frame never decides from its tree
    if (dot(f.zw, f.zw) > 0.0) {
        vec2 a = shadowFootprintMinMax(f.xy + float(2 * node) * f.zw);
        vec2 b = shadowFootprintMinMax(f.xy + float(2 * node + 1) * f.zw);
        mm = vec2(min(a.x, b.x), max(a.y, b.y));
    }
    storeNode(ivec2(treeLevelOffset(1, n) + node, slice), face, encodeTreeNode(mm));
}
