#version 450
#extension GL_GOOGLE_include_directive : require
// A coarser tree level from the one below it, in the same texture (the levels' columns are
// disjoint, so the pass reads one range and writes another). With LS_CUBE_SHADOW the trees of a
// point light's six cube faces, one layer each (gl_GlobalInvocationID.z).
#include "epipolar_bindings.h"
#include "min_max_tree.glsl"
layout(local_size_x = 64) in;
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
layout(binding = LS_BINDING_TREE_LEVEL, rg16f) uniform image2DArray tree;
vec2 loadNode(ivec2 p, int face) { return imageLoad(tree, ivec3(p, face)).xy; }
void storeNode(ivec2 p, int face, vec2 v) { imageStore(tree, ivec3(p, face), vec4(v, 0.0, 0.0)); }
#else
layout(binding = LS_BINDING_TREE_LEVEL, rg16f) uniform image2D tree;
vec2 loadNode(ivec2 p, int face) { return imageLoad(tree, p).xy; }
void storeNode(ivec2 p, int face, vec2 v) { imageStore(tree, p, vec4(v, 0.0, 0.0)); }
#endif
#define LS_INT int
layout(push_constant) uniform Push {
#include "min_max_push_fields.h"
} pc;
#undef LS_INT

void main() {
    int node = int(gl_GlobalInvocationID.x);
    int slice = int(gl_GlobalInvocationID.y);
    int face = int(gl_GlobalInvocationID.z);
    // A cube face out of view has no first level to build on (pc.faces: a bit per face).
    if (node >= (pc.n >> pc.level) || ((pc.faces >> face) & 1) == 0) return;
    int src = treeLevelOffset(pc.level - 1, pc.n) + 2 * node;
    vec2 a = loadNode(ivec2(src, slice), face);
    vec2 b = loadNode(ivec2(src + 1, slice), face);
    storeNode(ivec2(treeLevelOffset(pc.level, pc.n) + node, slice), face, mergeTreeNodes(a, b));
}
