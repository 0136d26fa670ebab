// Layout of the 1D min/max binary trees: one row per slice, level l (1..levels) of a map of N
// texels holds N >> l nodes starting at column N - (N >> (l - 1)); node k of level l covers samples
// [k 2^l, (k + 1) 2^l - 1]. All levels share one texture of N - 1 columns (seed 000 flip/flops
// between two, as a pixel shader cannot read the texture it renders to; a compute pass reads one
// level and writes the next of the same storage image).
#ifndef LS_MIN_MAX_TREE_GLSL
#define LS_MIN_MAX_TREE_GLSL

int treeLevelOffset(int level, int n) { return n - (n >> (level - 1)); }

// fp16 with directed rounding: trees stored in 16 bits stay conservative only if minima round down
// and maxima round up (depths are in [0, 1]).
float roundDownToHalf(float x) {
    x = clamp(x, 0.0, 1.0);
    uint h = packHalf2x16(vec2(x, 0.0)) & 0xffffu;
    if (unpackHalf2x16(h).x > x && h > 0u) h -= 1u;
    return unpackHalf2x16(h).x;
}

float roundUpToHalf(float x) {
    x = clamp(x, 0.0, 1.0);
    uint h = packHalf2x16(vec2(x, 0.0)) & 0xffffu;
    if (unpackHalf2x16(h).x < x) h += 1u;
    return unpackHalf2x16(h).x;
}

#endif
