// Where in its froxel the injection samples froxel f, in [0, 1)^3 (0.5: the centre). The plain
// grid: the push block's point, every froxel's centre. The temporal mode (LS_FROXEL_NOISE): the
// froxel's own offsets from the blue-noise tile moved by the frame's step (pc.jitter.xyz, the R3
// sequence), so that each froxel's points over the frames are a low-discrepancy sequence of its
// own and neighbouring froxels sample far-apart points in the same frame; they spread over the
// middle pc.jitter.w of the froxel along each axis.
#ifndef LS_FROXEL_JITTER_GLSL
#define LS_FROXEL_JITTER_GLSL

#if defined(LS_FROXEL_NOISE) && LS_FROXEL_NOISE
layout(binding = LS_BINDING_FROXEL_NOISE, r32f) uniform readonly image2D froxelNoise;

// The tile's value for froxel f moved by the frame's step, in [0, 1) on each axis.
vec3 froxelNoiseAt(ivec3 f) {
    ivec2 wrap = imageSize(froxelNoise) - 1;  // a power of two
    // Each slice reads another part of the tile, and each axis its own offset within it: the
    // tile's values are blue within a window, unrelated between windows far apart.
    ivec2 p = f.xy + f.z * ivec2(23, 41);
    vec3 b = vec3(imageLoad(froxelNoise, p & wrap).r,
                  imageLoad(froxelNoise, (p + ivec2(32, 13)) & wrap).r,
                  imageLoad(froxelNoise, (p + ivec2(11, 45)) & wrap).r);
    return fract(b + pc.jitter.xyz);
}

// Across the column only by pc.shift.z's share: the per-pixel history keeps each column's ray, for
// its pixels to weigh by their distance to it.
vec3 froxelJitter(ivec3 f) {
    return 0.5 + pc.jitter.w * vec3(pc.shift.zz, 1.0) * (froxelNoiseAt(f) - 0.5);
}

// Where along its lit part a slab's slice takes the shadow and cookie: anywhere in it over the
// frames, since the slice's integral is whole and only the shadow is a point sample; its middle,
// as the plain grid's, where the points spread over nothing (pc.jitter.w 0: the per-pixel
// history's frames in which only a light moved).
float froxelSlabPoint(ivec3 f) { return pc.jitter.w > 0.0 ? froxelNoiseAt(f).z : 0.5; }
#else
vec3 froxelJitter(ivec3 f) { return pc.jitter.xyz; }
float froxelSlabPoint(ivec3 f) { return 0.5; }
#endif

#endif
