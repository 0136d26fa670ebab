#version 450
#extension GL_GOOGLE_include_directive : require
// What the first marking and the first march draw in the march's order (marchTexel) when the march
// takes the tiles' samples from the list: the texels that can hold a ray-marching sample, as
// rectangles of two triangles each (2P - 1 of them for P phases, marchCoverVertices in
// passes/epipolar/epipolar_shaders.h). Those are block 0 (the initial grid and the lines' first
// samples), the first four columns of every other block (the lines' first samples of the other
// phases) and the tile rows of the list's first `count` slots, block after block; they do not
// overlap. Every other texel of the tiles is a slot past the count, which the marking discards:
// on lavapipe each of those fragments ran the marking's shader for nothing, most of the pass's
// time (docs/epipolar.md, node 7). Without the list, or where it overflowed (every texel then
// marks its own sample), the first rectangle is the whole texture and the others are empty.
#include "epipolar_constants.glsl"
#include "epipolar_bindings.h"
layout(std430, binding = LS_BINDING_MARCH_LIST) readonly buffer MarchList {
    uint count;
} marchList;

void main() {
    int rect = gl_VertexIndex / 6, corner = gl_VertexIndex % 6;
    int phases = int(epipolar.march.x);
    int logPhases = findLSB(max(phases, 1));
    int across = int(epipolar.march.y);
    ivec2 size = marchBlockSize(logPhases);
    ivec2 extent = phases <= 1 ? ivec2(epipolar.sampling.yx)
                               : size * ivec2(across, phases / max(across, 1));
    int run = phases <= 1 ? 0 : marchTileRun(logPhases);
    bool listed = run > 0 && marchesFromList() &&
                  marchList.count <= uint(marchListCapacity(logPhases));
    ivec2 lo = ivec2(0), hi = ivec2(0);  // the rectangle's texels: [lo, hi)
    if (!listed) {
        if (rect == 0) hi = extent;
    } else if (rect == 0) {
        hi = size;
    } else {
        // Rectangles 1 to P - 1: block b's first four columns; P to 2P - 2: block b's list rows.
        bool rows = rect >= phases;
        int block = rows ? rect - phases + 1 : rect;
        ivec2 origin = ivec2(block & (across - 1), block >> findLSB(across)) * size;
        if (!rows) {
            lo = origin;
            hi = origin + ivec2(4, size.y);
        } else {
            // The block's slots: (block - 1) run slices onwards, 16 to a tile, run tiles a row.
            int perBlock = run * int(epipolar.sampling.x);
            int slots = clamp(int(marchList.count) - (block - 1) * perBlock, 0, perBlock);
            int tileRows = (slots + 16 * run - 1) / (16 * run);
            lo = origin + ivec2(4, 0);
            hi = origin + ivec2(4 + 4 * run, 4 * tileRows);
        }
    }
    // Two triangles: (lo, (hi.x, lo.y), (lo.x, hi.y)) and ((hi.x, lo.y), hi, (lo.x, hi.y)).
    const ivec2 pick[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1),
                                   ivec2(0, 1));
    vec2 texel = vec2(mix(lo, hi, bvec2(pick[corner])));
    gl_Position = vec4(texel / vec2(extent) * 2.0 - 1.0, 0.0, 1.0);
}
