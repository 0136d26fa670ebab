// Layout of the 1D min/max binary trees: one row per slice, level l (1..levels) of a map of N
// texels holds N >> l nodes starting at column N - (N >> (l - 1)); node k of level l covers samples
// [k 2^l, (k + 1) 2^l - 1]. All levels share one texture of N - 1 columns (seed 000 flip/flops
// between two, as a pixel shader cannot read the texture it renders to; a compute pass reads one
// level and writes the next of the same storage image).
#ifndef LS_MIN_MAX_TREE_GLSL
#define LS_MIN_MAX_TREE_GLSL

int treeLevelOffset(int level, int n) { return n - (n >> (level - 1)); }

// Nodes hold (min z, max z) of standard depth as float16 values of 1 - z, rounded outwards. Under a
// perspective light z = f/(f-n) (1 - n/d) crowds against 1, where float16 steps by 2^-11: a step of
// about 2^-11 d^2 / n in distance, metres a few metres from a spot whose near plane is centimetres,
// and a tree rounded outwards by that much decides almost nothing. 1 - z crowds against 0, where
// float16 keeps its 11 significant bits. 1 - h is exact in float32 for every float16 h in [0, 1]
// (h is a multiple of 2^-24, and of 2^-11 above 1/2), so decoding loses nothing. Subnormal float16
// values, which a device may flush to zero, are never stored: they round outwards to 0 or 2^-14
// (z within 6e-5 of 1: hundreds of metres from a spot whose near plane is a few centimetres).
const uint kSmallestNormalHalf = 0x0400u;
float halfValue(uint h) { return unpackHalf2x16(h).x; }

// The smallest float16 h with 1 - h <= z: min z, rounded down.
float encodeTreeMin(float z) {
    z = clamp(z, 0.0, 1.0);
    uint h = packHalf2x16(vec2(1.0 - z, 0.0)) & 0xffffu;
    if (1.0 - halfValue(h) > z) ++h;
    if (h > 0u && 1.0 - halfValue(h - 1u) <= z) --h;
    if (h > 0u && h < kSmallestNormalHalf) h = kSmallestNormalHalf;
    return halfValue(h);
}

// The largest float16 h with 1 - h >= z: max z, rounded up.
float encodeTreeMax(float z) {
    z = clamp(z, 0.0, 1.0);
    uint h = packHalf2x16(vec2(1.0 - z, 0.0)) & 0xffffu;
    if (h > 0u && 1.0 - halfValue(h) < z) --h;
    if (h < 0x3c00u && 1.0 - halfValue(h + 1u) >= z) ++h;
    if (h < kSmallestNormalHalf) h = 0u;
    return halfValue(h);
}

// A node as stored from (min z, max z), and back.
vec2 encodeTreeNode(vec2 minMax) { return vec2(encodeTreeMin(minMax.x), encodeTreeMax(minMax.y)); }
vec2 decodeTreeNode(vec2 stored) { return 1.0 - stored; }
// The parent of two stored nodes: the min of their min z is the max of their 1 - min z.
vec2 mergeTreeNodes(vec2 a, vec2 b) { return vec2(max(a.x, b.x), min(a.y, b.y)); }

#endif
