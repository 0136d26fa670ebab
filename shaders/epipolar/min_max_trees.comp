#version 450
#extension GL_GOOGLE_include_directive : require
// Every level of one slice's min/max tree in one workgroup, from the shadow map: a level-1 node
// covers two samples along the slice's line and keeps the min and max of every texel their
// filtering can read, so the accelerated march decides exactly as visiting every texel would; a
// coarser node merges its two children. Each of the 64 threads builds the level-1 nodes of one run
// of the line and the levels above them within the run (a binary counter of pending nodes), and
// the runs' roots meet in shared memory for the last six levels. One dispatch instead of one per
// level: on lavapipe the per-level passes of a 2048^2 map cost about 9 ms of dispatches and
// barriers at 1920x1080, and each level-1 invocation its own set-up for one node.
// With LS_CUBE_SHADOW the six faces of a point light's cube at once: face gl_WorkGroupID.z's trees
// in its array layer.
// A slice's rays all start at or past the camera's point on its line when the camera projects in
// front of the light's plane (below): the nodes before that point are never read and not built
// (about half of a sun's lines, whose camera point lies inside the map).
#include "min_max_tree.glsl"
#include "epipolar_constants.glsl"
#include "frame.glsl"
#include "epipolar_bindings.h"
layout(local_size_x = 64) in;
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
layout(binding = LS_BINDING_TREE_SHADOW_MAP) uniform sampler2DArray shadowMap;
layout(binding = LS_BINDING_TREE_OUT, rg16f) uniform writeonly image2DArray tree;
void storeNode(ivec2 p, int face, vec2 v) { imageStore(tree, ivec3(p, face), vec4(v, 0.0, 0.0)); }
#else
layout(binding = LS_BINDING_TREE_SHADOW_MAP) uniform sampler2D shadowMap;
layout(binding = LS_BINDING_TREE_OUT, rg16f) uniform writeonly image2D tree;
void storeNode(ivec2 p, int face, vec2 v) { imageStore(tree, p, vec4(v, 0.0, 0.0)); }
#endif
layout(binding = LS_BINDING_TREE_UV_FRAME) uniform sampler2D sliceUvFrame;
#include "shadow.glsl"

const int kThreads = 64;
const int kMaxRunLevels = 15;  // a run of 2^15 level-1 nodes: maps far beyond any device's limit
shared vec2 roots[kThreads];

// Node `node` of `level`, stored where the march reads it, if the level has it (level l holds
// n >> l nodes; a node it holds has both its children).
void storeIfHeld(int level, int node, int slice, int face, int n, vec2 v) {
    if (node < (n >> level)) storeNode(ivec2(treeLevelOffset(level, n) + node, slice), face, v);
}

void main() {
    int t = int(gl_LocalInvocationID.x);
    int slice = int(gl_WorkGroupID.y);
    int face = int(gl_WorkGroupID.z);
    int n = int(frame.shadowInfo.x);
    int levels = int(epipolar.marching.x);
    // A face out of view: no ray marches its lines, nothing reads its trees (the whole workgroup
    // returns, so the barriers below stay uniform).
    if (!cubeFaceReachesView(face)) return;
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
    shadowFace = face;
#endif
    vec4 f = texelFetch(sliceUvFrame, ivec2(slice, face), 0);
    bool framed = dot(f.zw, f.zw) > 0.0;  // a slice without a frame never decides from its tree
    // Each thread's run: the fewest level-1 nodes, a power of two, with which 64 runs cover n / 2.
    int firstLevel = n >> 1;
    int run = 1, runLevels = 0;
    while (run * kThreads < firstLevel && runLevels < kMaxRunLevels) {
        run *= 2;
        ++runLevels;
    }
    // Nodes before `first` are skipped. A node over skipped ones is never read either (it starts
    // before `first`); it is built from the unframed value, which decides nothing.
    int first = framed ? firstBuiltTreeNode(f, face) : 0;
    vec2 unframed = encodeTreeNode(vec2(0.0, 1.0));
    vec2 pending[kMaxRunLevels + 2];  // pending[l]: the left child waiting at level l
    for (int l = 0; l < kMaxRunLevels + 2; ++l) pending[l] = unframed;
    vec2 v = unframed;
    for (int c = clamp(first - t * run, 0, run); c < run; ++c) {
        int node = t * run + c;
        if (node >= firstLevel) break;
        vec2 mm = vec2(0.0, 1.0);
        if (framed) {
            vec2 a = shadowFootprintMinMax(f.xy + float(2 * node) * f.zw);
            vec2 b = shadowFootprintMinMax(f.xy + float(2 * node + 1) * f.zw);
            mm = vec2(min(a.x, b.x), max(a.y, b.y));
        }
        v = encodeTreeNode(mm);
        storeNode(ivec2(treeLevelOffset(1, n) + node, slice), face, v);
        // A right child completes its parent, up to the run's root (level 1 + runLevels). The
        // stored values are float16 already, so merging before storing is the same as merging
        // what was stored.
        int level = 1, index = node;
        while ((index & 1) == 1 && level <= runLevels) {
            v = mergeTreeNodes(pending[level], v);
            index >>= 1;
            ++level;
            storeIfHeld(level, index, slice, face, n, v);
        }
        pending[level] = v;
    }
    // The runs' roots, level 1 + runLevels, node t: the last six levels across the threads.
    roots[t] = v;
    barrier();
    int level = 1 + runLevels;
    for (int count = kThreads >> 1; count > 0 && level < levels; count >>= 1) {
        ++level;
        vec2 m = t < count ? mergeTreeNodes(roots[2 * t], roots[2 * t + 1]) : vec2(0.0);
        barrier();
        if (t < count) {
            roots[t] = m;
            storeIfHeld(level, t, slice, face, n, m);
        }
        barrier();
    }
}
