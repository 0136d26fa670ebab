// Epipolar's own constants (epipolar_constants_fields.h, std140), beside the frame's (frame.glsl):
// the light's, or in a cube face's passes the face's.
#ifndef LS_EPIPOLAR_CONSTANTS_GLSL
#define LS_EPIPOLAR_CONSTANTS_GLSL
#include "epipolar_bindings.h"
#include "frame.glsl"

layout(std140, set = 0, binding = LS_BINDING_EPIPOLAR) uniform EpipolarConstants {
#define LS_VEC4 vec4
#include "epipolar_constants_fields.h"
#undef LS_VEC4
} epipolar;

// World -> clip of the shadow map the pass reads. With LS_CUBE_SHADOW a point light's cube: one
// face read as a spot light's map, its matrix from the frame's six (`face` is ignored without).
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
mat4 shadowViewProj(int face) { return frame.cubeFaceViewProj[face]; }
#else
mat4 shadowViewProj(int face) { return frame.lightViewProj; }
#endif
// Whether cube face `face` reaches the view (always, without a cube): a face that does not holds
// no part of any of the frame's rays, and its lines and trees are not built.
bool cubeFaceReachesView(int face) { return ((int(epipolar.cubeFaces.x) >> face) & 1) != 0; }

// The first level-1 tree node any ray of the slice whose line is `f` (its shadow-map uv origin and
// step, slice_uv_frame.comp) can read: min_max_trees.comp builds the slice's tree from there on.
// The march reads a node only at or past the line sample where its ray enters the map, ceil(ta)
// (ray_march.frag). A point C + t v of a camera ray projects to (Xc + t Xv).xy / (Xc.w + t Xv.w),
// which moves by (Xv.xy Xc.w - Xc.xy Xv.w) / w^2, the line's direction over w^2: wherever w > 0
// it only moves forward along the line. With the camera in front of the light's plane (Xc.w > 0),
// w stays positive from the camera to every marched point (w is linear in t, and positive in the
// map's frustum), so every ray enters the map at or past the camera's own projection. Two samples
// of slack cover the march's rounding of ta. Behind the light's plane a ray's projection comes
// from infinity: 0.
int firstBuiltTreeNode(vec4 f, int face) {
    vec4 Xc = shadowViewProj(face) * vec4(frame.cameraPos.xyz, 1.0);
    if (!(Xc.w > 1e-6)) return 0;
    vec2 camera = Xc.xy / Xc.w * 0.5 + 0.5;
    float tau = dot(camera - f.xy, f.zw) / dot(f.zw, f.zw);
    if (!(tau > 2.0)) return 0;  // before the line's start, or NaN: build it all
    return (int(floor(min(tau, 1e9))) - 2) >> 1;
}

// The march's order: the ray march renders its samples, and the stencil that marks them, into
// textures of their own whose texels are ordered so that the samples marched together are
// neighbours. With P phases (epipolar.march.x: the initial step, where it divides the samples per
// line S), the texture is P blocks of S / P x 4 by slices / 4 texels, in rows of epipolar.march.y
// (as large as the samples', S x slices when P is a square power of two). Sample k = q P + r of
// slice j = 4 u + v (v < 4) is texel (4 q + v, u) of block r when r = 0 or q = 0: the initial grid
// fills block 0 and each 4 x 4 texels hold one k of 16 neighbouring slices, which march nearly
// alike (so do the first samples of the lines, cut at 1, 2, 4, ... next to a light on screen,
// in the first four columns of the other blocks). The samples with r > 0 and q > 0, which the
// march takes only where refinement put them (on both sides of a depth break: a few consecutive k
// of neighbouring slices), are numbered m = (q - 1)(P - 1) + r - 1 along their line; block
// 1 + m / (S / P - 1) holds them past its first four columns, 4 slices at each m in turn, 16 to a
// tile of 4 x 4 texels, so a break's samples share tiles. (With a block per phase k % P, as
// before, each refined sample was alone in its 4 x 4 texels: the atrium's 16394 refined samples,
// a quarter of those it marches, took about 70% of its march's time at 1920x1080.) P and the
// blocks per row are powers of two (shifts below). The tiles need the slices a multiple of 16;
// otherwise every sample keeps its phase's block. A device shades blocks of neighbouring pixels
// together (a GPU 2 x 2 quads, lavapipe 4 x 4 blocks in 8-wide vectors), and the stencil masks out
// the samples a block does not march. Every other samples x slices texture keeps sample k of slice
// j at (k, j). P = 1: the march's order is that.

// (a / b, a % b) for a >= 0 and b > 0, from the float quotient corrected by one (it is within one
// of a / b for a and b below 2^24, far beyond any texture's size): lavapipe has no vector integer
// division and divides lane by lane, and the march's order divides by uniforms that are not
// powers of two (P - 1, S / P - 1, the block's size) in every pass that reads its textures.
ivec2 divMod(int a, int b) {
    int q = int(float(a) / float(b));
    int r = a - q * b;
    if (r < 0) return ivec2(q - 1, r + b);
    if (r >= b) return ivec2(q + 1, r - b);
    return ivec2(q, r);
}
// A block of the march's texture: S / P x 4 by slices / 4 texels.
ivec2 marchBlockSize(int logPhases) {
    return ivec2((int(epipolar.sampling.y) >> logPhases) * 4, int(epipolar.sampling.x) >> 2);
}
// How many q >= 1 of a line each of the blocks 1 to P - 1 holds (S / P - 1), 0 where they keep a
// block per phase.
int marchTileRun(int logPhases) {
    int run = (int(epipolar.sampling.y) >> logPhases) - 1;
    return (int(epipolar.sampling.x) & 15) == 0 ? run : 0;
}
ivec2 marchTexel(int k, int slice) {
    int phases = int(epipolar.march.x);
    if (phases <= 1) return ivec2(k, slice);
    int logPhases = findLSB(phases), across = int(epipolar.march.y);
    ivec2 size = marchBlockSize(logPhases);
    int q = k >> logPhases, block = k & (phases - 1);
    ivec2 t = ivec2(4 * q + (slice & 3), slice >> 2);
    int run = marchTileRun(logPhases);
    if (block != 0 && q != 0 && run > 0) {
        ivec2 m = divMod((q - 1) * (phases - 1) + block - 1, run);
        block = 1 + m.x;
        int e = (slice >> 2) * 4 * run + 4 * m.y + (slice & 3);  // 4 slices at each m in turn
        ivec2 tile = divMod(e >> 4, run);
        t = ivec2(4 + 4 * tile.y + (e & 3), 4 * tile.x + ((e >> 2) & 3));
    }
    return ivec2(block & (across - 1), block >> findLSB(across)) * size + t;
}
// Where the march's texel t lies: x its block, y its place among the block's tiles (16 to a tile,
// row by row within it, the tiles row by row), or -1 outside the tiles; zw its place in the block.
ivec4 marchTexelPlace(ivec2 t, int logPhases) {
    ivec2 size = marchBlockSize(logPhases);
    ivec2 x = divMod(t.x, size.x), y = divMod(t.y, size.y);
    int block = (y.x << findLSB(int(epipolar.march.y))) + x.x;
    int run = marchTileRun(logPhases);
    int place = -1;
    if (block != 0 && x.y >= 4 && run > 0)
        place = 16 * ((y.y >> 2) * run + ((x.y - 4) >> 2)) + 4 * (y.y & 3) + (x.y & 3);
    return ivec4(block, place, x.y, y.y);
}
// The sample (k, slice) at the march's place `at` (marchTexelPlace).
ivec2 sampleOfMarchPlace(ivec4 at, int logPhases) {
    if (at.y >= 0) {
        int run = marchTileRun(logPhases);
        ivec2 e = divMod(at.y, 4 * run);
        ivec2 m = divMod((at.x - 1) * run + (e.y >> 2), (1 << logPhases) - 1);
        return ivec2(((m.x + 1) << logPhases) + m.y + 1, 4 * e.x + (e.y & 3));
    }
    return ivec2(((at.z >> 2) << logPhases) + at.x, at.w * 4 + (at.z & 3));
}
// The sample (k, slice) at the march's texel t.
ivec2 sampleOfMarchTexel(ivec2 t) {
    int phases = int(epipolar.march.x);
    if (phases <= 1) return t;
    int logPhases = findLSB(phases);
    return sampleOfMarchPlace(marchTexelPlace(t, logPhases), logPhases);
}

// The march list (marchesFromList in epipolar_constants.h): the refinement appends the samples of
// the tiles it marches, and the first march takes slot i of the list at the tiles' i-th texel (in
// marchTexelPlace's order, block after block), so that the list fills whole tiles; each sample's
// value still goes to its own texel, marchTexel, where the later passes read it. The list holds an
// eighth of the tiles' samples (far more than depth breaks take: the atrium's, at 1920x1080, take
// 1.7%); a frame whose refinement gives it more marches them in their tiles instead, every texel
// its own sample, as without a list. The list's entries: k | slice << 16.
bool marchesFromList() { return epipolar.march.z > 0.5; }
int marchListCapacity(int logPhases) {
    return (((1 << logPhases) - 1) * marchTileRun(logPhases) * int(epipolar.sampling.x)) >> 3;
}
// The list's slot that the march's texel t marches, or -1 where it marches its own sample, `at`:
// outside the tiles, or without a list, or where the list's `count` ran past it.
int marchListSlot(ivec2 t, uint count, out ivec2 at) {
    int phases = int(epipolar.march.x);
    if (phases <= 1) {
        at = t;
        return -1;
    }
    int logPhases = findLSB(phases);
    ivec4 place = marchTexelPlace(t, logPhases);
    if (place.y >= 0 && marchesFromList() && count <= uint(marchListCapacity(logPhases)))
        return (place.x - 1) * marchTileRun(logPhases) * int(epipolar.sampling.x) + place.y;
    at = sampleOfMarchPlace(place, logPhases);
    return -1;
}
uint marchListEntry(ivec2 p) { return uint(p.x) | (uint(p.y) << 16); }
ivec2 marchListSample(uint entry) { return ivec2(entry & 0xffffu, entry >> 16); }
// Whether sample k of a line is one of the tiles' (q >= 1, r >= 1, with tiles).
bool inMarchTiles(int k) {
    int phases = int(epipolar.march.x);
    if (phases <= 1) return false;
    int logPhases = findLSB(phases);
    return (k & (phases - 1)) != 0 && (k >> logPhases) != 0 && marchTileRun(logPhases) > 0;
}

// Whether a sample is valid (on the screen, on a slice that enters it), from its epipolar z: the
// coordinates pass leaves -1 where it is not.
bool validSampleZ(float z) { return z > 0.0; }

// Whether the samples carry the shadowed fraction (ratio mode) rather than Lin. A point or spot
// light in a non-uniform medium carries Lin whatever the settings (interpolatesLin in
// epipolar_constants.h), which the specialisation constants already say: its variants hold no
// ratio-mode code, which lavapipe would run untaken.
bool carriesShadowedFraction() {
    if (kMedia != 0 && kLightType != LIGHT_DIRECTIONAL) return false;
    return epipolar.marching.y > 0.5;
}

#endif
