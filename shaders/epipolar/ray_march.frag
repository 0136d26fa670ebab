#version 450
#extension GL_GOOGLE_include_directive : require
// Ray marching of the ray-marching samples (stencil-tested), along their slice's line in the shadow
// map, skipping whole lit or shadowed runs with the slice's 1D min/max tree. Sample i of the line
// (uv = origin + i dir) decides the visibility of the ray over (i - 1, i], split where the ray's
// depth passes one of its texels' (march.glsl); the ray's light-space depth is affine in i, its
// distance is perspective-correct (1/w and d/w are affine in i).
// With LS_CUBE_SHADOW (a point light's cube map) the ray is cut where the major axis of P - L
// changes, as the fix-up's march cuts it (marchRayCube in march.glsl), and each part is marched
// along its slice's line in its face's map (the face's row of the line frames, its layer of the
// trees and of the map), nearest first, into one accumulator: one pass for the six faces.
// With LS_COUNT_STEPS (DebugOptions::countSteps) each invocation adds what it did into its slice's
// row of a storage buffer (kCount* below); without it the variant has no buffer and no atomics.
#include "camera.glsl"
#include "epipolar_constants.glsl"
#include "min_max_tree.glsl"
#include "epipolar_bindings.h"
layout(binding = LS_BINDING_MARCH_COORDINATES) uniform sampler2D coordinates;
layout(binding = LS_BINDING_MARCH_EPIPOLAR_Z) uniform sampler2D epipolarZ;
layout(binding = LS_BINDING_MARCH_UV_FRAME) uniform sampler2D sliceUvFrame;
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
layout(binding = LS_BINDING_MARCH_END_POINTS) uniform sampler2D sliceEndPoints;
#endif
#if LS_TREES && defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
layout(binding = LS_BINDING_MARCH_TREES) uniform sampler2DArray trees;  // a layer per face
#elif LS_TREES
layout(binding = LS_BINDING_MARCH_TREES) uniform sampler2D trees;
#endif
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
layout(binding = LS_BINDING_SHADOW_MAP) uniform sampler2DArray shadowMap;
#else
layout(binding = LS_BINDING_SHADOW_MAP) uniform sampler2D shadowMap;
#endif
#if LS_NEEDS_TABLE
layout(binding = LS_BINDING_POINT_TABLE) uniform sampler2D pointTable;
#endif
#if LS_LIGHT_COLOR
layout(binding = LS_BINDING_LIGHT_COLOR) uniform sampler2D lightColorMap;
#endif
#if defined(LS_COUNT_STEPS) && LS_COUNT_STEPS
// One row of kCountStride counters per slice: a row's sums stay far below 2^32 at any profile,
// where one counter for the whole frame would wrap at 1920x1080. The plugin adds the rows up.
#include "step_counts_layout.h"
const int kCountSamples = LS_COUNT_SAMPLES;
const int kCountRays = LS_COUNT_RAYS;
const int kCountLineSteps = LS_COUNT_LINE_STEPS;
const int kCountTreeNodes = LS_COUNT_TREE_NODES;
const int kCountDegenerateRays = LS_COUNT_DEGENERATE_RAYS;
const int kCountDegenerateSteps = LS_COUNT_DEGENERATE_STEPS;
const int kCountListed = LS_COUNT_LISTED;
const int kCountUnbuiltNodes = LS_COUNT_UNBUILT_NODES;
const int kCountStride = LS_COUNT_STRIDE;
layout(std430, binding = LS_BINDING_MARCH_STEP_COUNTS) buffer StepCounts { uint stepCounts[]; };
uint countedLookups = 0u;
#define LS_COUNT_LOOKUP() ++countedLookups
#define COUNT(x) x
#else
#define COUNT(x)
#endif
#include "march.glsl"
// Each sample's value is stored at its own texel (marchTexel), which is not the fragment's where it
// came from the march list. Stores make the stencil test late unless asked otherwise: every
// texel's invocation would run (and count), not only the ray-marching samples'.
layout(early_fragment_tests) in;
layout(binding = LS_BINDING_MARCH_OUT, rgba16f) uniform writeonly image2D marched;
layout(std430, binding = LS_BINDING_MARCH_LIST) readonly buffer MarchList {
    uint count;
    uint entries[];
} marchList;

#if defined(LS_COUNT_STEPS) && LS_COUNT_STEPS
uint counted[LS_COUNTERS] = uint[LS_COUNTERS](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
void flushCounts(int slice) {
    for (int k = 0; k < LS_COUNTERS; ++k)
        if (counted[k] != 0u) atomicAdd(stepCounts[slice * kCountStride + k], counted[k]);
}
#endif

const bool kMinMaxTrees = LS_TREES != 0;

// A spot's or the sun's variants keep their code as it was before a cube's six faces shared this
// pass; the cube's sits beside it (LS_CUBE_SHADOW). Written as one path for both (the cube's
// marchInMap called once with face 0), the spot's variant rendered the same bits in the same time,
// but the soak test's window (window_room, a spot, under lavapipe) then held 16 MiB more in about
// one run in three, at a resize, and failed (docs/epipolar.md, "A point light's cube map").
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
vec2 treeNode(int level, int node, int slice, int face, int n) {
#if LS_TREES
    ivec3 p = ivec3(treeLevelOffset(level, n) + node, slice, face);
    return decodeTreeNode(texelFetch(trees, p, 0).xy);
#else
    return vec2(0.0, 1.0);
#endif
}
#define LS_TREE_NODE(level, node, slice, r, n) treeNode(level, node, slice, r.face, n)
#else
vec2 treeNode(int level, int node, int slice, int n) {
#if LS_TREES
    ivec2 p = ivec2(treeLevelOffset(level, n) + node, slice);
    return decodeTreeNode(texelFetch(trees, p, 0).xy);
#else
    return vec2(0.0, 1.0);
#endif
}
#define LS_TREE_NODE(level, node, slice, r, n) treeNode(level, node, slice, n)
#endif

struct LineRay {
    float ta, tb;        // the ray's segment in line samples
    FrustumSegment seg;  // ... in metres and depth (a in [0, 1] from ta to tb)
    vec2 origin, dir;    // the slice's line
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
    int face;  // whose trees (a cube face's layer)
#endif
};

// Where line sample t lies on the ray's segment, held at its ends: a sample past the end (the last
// one decides the visibility of the part before it) takes the end's depth, never an extrapolation,
// which for a segment much shorter than a texel would be anything. A segment shorter than a sample
// lies within the one sample at or after ta, which takes all of it.
float lineParam(LineRay r, float t) {
    if (r.tb > r.ta) return clamp((t - r.ta) / (r.tb - r.ta), 0.0, 1.0);
    return t >= r.ta ? 1.0 : 0.0;
}

float depthAt(LineRay r, int i) { return mix(r.seg.z0, r.seg.z1, lineParam(r, float(i))); }

// The level to try next at sample i: from `level` (i is aligned to it), down until its node fits
// within [0, min(last, n - 1)], or up while the parent starts at i and fits too.
int climb(int i, int level, int last, int n, int levels) {
    if (!kMinMaxTrees || i < 0) return 0;
    int end = min(last, n - 1);
    while (level > 0 && i + (1 << level) - 1 > end) --level;
    while (level < levels && (i & ((2 << level) - 1)) == 0 && i + (2 << level) - 1 <= end) ++level;
    return level;
}

// Each iteration adds one step, through advancePieces alone: a line sample (it decides the ray over
// (i - 1, i], split where the ray's depth passes a texel's) or a tree node taken whole, reached by
// an inner loop of look-ups down the tree.
void marchLine(inout Inscatter acc, LineRay r, int slice) {
    int n = int(frame.shadowInfo.x);
    int levels = int(epipolar.marching.x);
    int i = int(ceil(r.ta));
    int last = int(ceil(r.tb));
    int level = climb(i, 0, last, n, levels);
#if defined(LS_COUNT_STEPS) && LS_COUNT_STEPS
    // Where the trees pass began this slice's tree: a node before it was never built.
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
    int firstBuilt = firstBuiltTreeNode(vec4(r.origin, r.dir), r.face);
#else
    int firstBuilt = firstBuiltTreeNode(vec4(r.origin, r.dir), 0);
#endif
#endif
    for (int guard = 0; i <= last && guard < 4 * n + 64; ++guard) {
        // Down from `level` to the coarsest node at i that is lit or shadowed throughout, or to
        // a line sample. The node's samples decide the ray over (i - 1, j], so its depths from
        // i - 1 on: a step split where the ray passes a texel's depth is never inside a node
        // taken whole.
        bool shadowed = false;
        int j = i;
        for (; level > 0; --level) {
            j = i + (1 << level) - 1;
            COUNT(++counted[kCountTreeNodes]);
            COUNT(if (((i >> level) << (level - 1)) < firstBuilt) ++counted[kCountUnbuiltNodes]);
            vec2 node = LS_TREE_NODE(level, i >> level, slice, r, n);
            float zi = compareDepth(depthAt(r, i - 1)), zj = compareDepth(depthAt(r, j));
            if (!kLightColor && max(zi, zj) <= node.x) break;  // lit throughout
            if (min(zi, zj) > node.y) {
                shadowed = true;
                break;
            }
        }
        ShadowFootprint fp = ShadowFootprint(false, vec4(1.0), vec2(0.0));  // lit
        vec3 color = vec3(1.0);
        vec4 cuts = vec4(0.0);
        int first = 4;
        float aA = 0.0, aB;
        if (level == 0) {
            COUNT(++counted[kCountLineSteps]);
            vec2 uv = r.origin + float(i) * r.dir;
            fp = shadowFootprint(uv);
            color = lightColorAt(uv);
            aA = lineParam(r, float(i - 1));
            aB = lineParam(r, float(i));
            if (footprintCrossings(r.seg, fp, aA, aB, cuts)) first = 0;
            ++i;
            level = climb(i, 0, last, n, levels);
        } else {
            aB = lineParam(r, float(j));
            i = j + 1;
            level = climb(i, level, last, n, levels);
        }
        advancePieces(acc, r.seg, fp, color, cuts, first, aA, aB, shadowed);
    }
}

#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
// The ray's part [t0, t1] in cube face `face`'s map: its part in the face's frustum marched along
// the slice's line, lit before it. The part after the frustum is the caller's to advance through
// (lit).
void marchInMap(inout Inscatter acc, vec3 C, vec3 v, float t0, float t1, int slice, int face) {
    float f0 = t0, f1 = t1;
    mat4 viewProj = shadowViewProj(face);
    clipToFrustum(viewProj, C, v, f0, f1);
    vec4 frameUv = texelFetch(sliceUvFrame, ivec2(slice, face), 0);
    if (f0 < f1 && dot(frameUv.zw, frameUv.zw) > 0.0) {
        advance(acc, f0, vec3(1.0));
        vec4 X0 = viewProj * vec4(C + f0 * v, 1.0);
        vec4 X1 = viewProj * vec4(C + f1 * v, 1.0);
        vec2 uv0 = X0.xy / X0.w * 0.5 + 0.5, uv1 = X1.xy / X1.w * 0.5 + 0.5;
        LineRay r;
        r.origin = frameUv.xy;
        r.dir = frameUv.zw;
        r.face = face;
        float invLen2 = 1.0 / dot(r.dir, r.dir);
        r.ta = dot(uv0 - r.origin, r.dir) * invLen2;
        r.tb = dot(uv1 - r.origin, r.dir) * invLen2;
        r.seg = FrustumSegment(f0, f1, 1.0 / X0.w, 1.0 / X1.w, toStandardDepth(X0.z / X0.w),
                               toStandardDepth(X1.z / X1.w));
        // The ray should lie on its slice's line. It does not when its projection degenerates to
        // a point (a ray along the light's direction, a camera at the light) or runs against the
        // line: then it is marched on its own, texel by texel as brute force would, each step split
        // where the ray passes a texel's depth as on the line.
        vec2 across = vec2(-r.dir.y, r.dir.x) * inversesqrt(dot(r.dir, r.dir));
        float offLine = max(abs(dot(uv0 - r.origin, across)), abs(dot(uv1 - r.origin, across)));
        COUNT(++counted[kCountRays]);
        if (r.tb >= r.ta && offLine * frame.shadowInfo.x <= 0.5) {
            marchLine(acc, r, slice);
        } else {
            marchFrustumSegmentOf(viewProj, acc, C, v, f0, f1, 0u, true);
            COUNT(++counted[kCountDegenerateRays]);
            COUNT(counted[kCountDegenerateSteps] += countedLookups);
        }
    }
}

vec3 marchSample(vec3 C, vec3 v, float S, int slice) {
    float t0, t1;
    lightInterval(C, v, S, t0, t1);
    if (!(t0 < t1)) return vec3(0.0);
    Inscatter acc = beginInscatter(C, v, t0);
    // Each face's part of [t0, t1] (a face out of view holds none), marched nearest first.
    float lo[6], hi[6];
    for (int f = 0; f < 6; ++f) {
        lo[f] = t0;
        hi[f] = cubeFaceReachesView(f) ? t1 : t0;
        clipToCubeFaceRegion(C, v, f, lo[f], hi[f]);
    }
    float done = t0;  // where the last part ended (the regions meet there, up to rounding)
    for (int n = 0; n < 6; ++n) {
        int next = -1;
        for (int f = 0; f < 6; ++f)
            if (lo[f] < hi[f] && (next < 0 || lo[f] < lo[next])) next = f;
        if (next < 0) break;
        float a = max(lo[next], done), b = hi[next];
        lo[next] = hi[next];
        if (!(a < b)) continue;
        shadowFace = next;
        marchInMap(acc, C, v, a, b, slice, next);
        advance(acc, b, vec3(1.0));
        done = b;
    }
    advance(acc, t1, vec3(1.0));
    return finishInscatter(acc, v);
}

#else
vec3 marchSample(vec3 C, vec3 v, float S, int slice) {
    float t0, t1;
    lightInterval(C, v, S, t0, t1);
    if (!(t0 < t1)) return vec3(0.0);
    Inscatter acc = beginInscatter(C, v, t0);
    float f0 = t0, f1 = t1;
    clipToFrustum(shadowViewProj(0), C, v, f0, f1);
    vec4 frameUv = texelFetch(sliceUvFrame, ivec2(slice, 0), 0);
    if (f0 < f1 && dot(frameUv.zw, frameUv.zw) > 0.0) {
        advance(acc, f0, vec3(1.0));
        vec4 X0 = shadowViewProj(0) * vec4(C + f0 * v, 1.0);
        vec4 X1 = shadowViewProj(0) * vec4(C + f1 * v, 1.0);
        vec2 uv0 = X0.xy / X0.w * 0.5 + 0.5, uv1 = X1.xy / X1.w * 0.5 + 0.5;
        LineRay r;
        r.origin = frameUv.xy;
        r.dir = frameUv.zw;
        float invLen2 = 1.0 / dot(r.dir, r.dir);
        r.ta = dot(uv0 - r.origin, r.dir) * invLen2;
        r.tb = dot(uv1 - r.origin, r.dir) * invLen2;
        r.seg = FrustumSegment(f0, f1, 1.0 / X0.w, 1.0 / X1.w, toStandardDepth(X0.z / X0.w),
                               toStandardDepth(X1.z / X1.w));
        // The ray should lie on its slice's line. It does not when its projection degenerates to
        // a point (a ray along the light's direction, a camera at the light) or runs against the
        // line: then it is marched on its own, texel by texel as brute force would, each step split
        // where the ray passes a texel's depth as on the line.
        vec2 across = vec2(-r.dir.y, r.dir.x) * inversesqrt(dot(r.dir, r.dir));
        float offLine = max(abs(dot(uv0 - r.origin, across)), abs(dot(uv1 - r.origin, across)));
        COUNT(++counted[kCountRays]);
        if (r.tb >= r.ta && offLine * frame.shadowInfo.x <= 0.5) {
            marchLine(acc, r, slice);
        } else {
            marchFrustumSegmentOf(shadowViewProj(0), acc, C, v, f0, f1, 0u, true);
            COUNT(++counted[kCountDegenerateRays]);
            COUNT(counted[kCountDegenerateSteps] += countedLookups);
        }
    }
    advance(acc, t1, vec3(1.0));
    return finishInscatter(acc, v);
}

#endif

void main() {
    // The fragment is the sample's texel in the march's order (marchTexel), or a slot of the march
    // list; p is the sample.
    ivec2 t = ivec2(gl_FragCoord.xy), p;
    int slot = marchListSlot(t, marchList.count, p);
    if (slot >= 0) p = marchListSample(marchList.entries[slot]);
    vec2 ndc = texelFetch(coordinates, p, 0).xy * 2.0 - 1.0;
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
    // Back onto the slice's line, off which the coordinates' rounding put it (RG16: 1.5e-5 of the
    // screen). A ray a few pixels from a point light passes millimetres from it, where such an
    // offset turns it by a hundredth of a radian: texels off the face's line, which would leave it
    // to be marched texel by texel across the whole face.
    vec4 ends = texelFetch(sliceEndPoints, ivec2(p.y, 0), 0);
    vec2 line = ends.zw - ends.xy;
    ndc = ends.xy + dot(ndc - ends.xy, line) / max(dot(line, line), 1e-20) * line;
#endif
    float z = texelFetch(epipolarZ, p, 0).r;
    vec3 v = rayDirection(ndc);
    vec3 C = frame.cameraPos.xyz;
    float S = rayLength(z, v);
    vec3 lin = marchSample(C, v, S, p.y);
#if defined(LS_COUNT_STEPS) && LS_COUNT_STEPS
    ++counted[kCountSamples];
    if (slot >= 0) ++counted[kCountListed];
    flushCounts(p.y);
#endif
    float defined = 1.0;
    if (carriesShadowedFraction()) {
        float t0, t1;
        lightInterval(C, v, S, t0, t1);
        vec3 unshadowed = unshadowedInscatter(C, v, t0, t1);
        lin = shadowedFraction(lin, unshadowed);
        // Where no light reaches the ray the fraction means nothing: alpha 0 keeps it out of
        // every later filter (outside a spot's cone, next to rays inside it).
        defined = any(greaterThan(unshadowed, vec3(0.0))) ? 1.0 : 0.0;
    } else {
        lin = storedLin(lin);  // samples carry Lin itself (Interpolation::Inscattering)
    }
    imageStore(marched, slot >= 0 ? marchTexel(p.x, p.y) : t, vec4(lin, defined));
}
