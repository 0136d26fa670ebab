#version 450
#extension GL_GOOGLE_include_directive : require
// A coarser tree level from the one below it, in the same texture (the levels' columns are
// disjoint, so the pass reads one range and writes another).
#include "epipolar_bindings.h"
#include "min_max_tree.glsl"
layout(local_size_x = 64) in;
layout(binding = LS_BINDING_TREE_LEVEL, rg16f) uniform image2D tree;
#define LS_INT int
layout(push_constant) uniform Push {
#include "min_max_push_fields.h"
} pc;
#undef LS_INT

void main() {
    int node = int(gl_GlobalInvocationID.x);
    int slice = int(gl_GlobalInvocationID.y);
    if (node >= (pc.n >> pc.level)) return;
    int src = treeLevelOffset(pc.level - 1, pc.n) + 2 * node;
    vec2 a = imageLoad(tree, ivec2(src, slice)).xy;
    vec2 b = imageLoad(tree, ivec2(src + 1, slice)).xy;
    imageStore(tree, ivec2(treeLevelOffset(pc.level, pc.n) + node, slice), vec4(mergeTreeNodes(a, b), 0.0, 0.0));
}
