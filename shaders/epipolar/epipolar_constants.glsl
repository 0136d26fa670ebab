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

// The march's order: the ray march renders its samples, and the stencil that marks them, into
// textures of their own whose texels are ordered so that the samples marched together are
// neighbours. With P phases (epipolar.march.x: the initial step, where it divides the samples per
// line S), sample k = q P + r of slice j = 4 u + v (v < 4) is texel (4 q + v, u) of phase r's
// block, S / P x 4 wide and slices / 4 tall, and the P blocks tile the texture in rows of
// epipolar.march.y (the march's texture is as large as the samples', S x slices when P is a
// square power of two). So the initial grid's ray-marching samples (r = 0) fill the first block,
// and each 4 x 4 texels hold one k of 16 neighbouring slices. A device shades blocks of
// neighbouring pixels together (a GPU 2 x 2 quads, lavapipe 4 x 4 blocks in 8-wide vectors): in
// the samples' own order the grid was one column in P, and most of every block the march shaded
// was masked out by the stencil; one k of neighbouring slices marches nearly alike. Every other
// samples x slices texture keeps sample k of slice j at (k, j). P = 1: the march's order is that.
ivec2 marchTexel(int k, int slice) {
    int phases = int(epipolar.march.x);
    if (phases <= 1) return ivec2(k, slice);
    int across = int(epipolar.march.y), r = k % phases;
    ivec2 block = ivec2(r % across, r / across) *
                  ivec2(int(epipolar.sampling.y) / phases * 4, int(epipolar.sampling.x) / 4);
    return block + ivec2(4 * (k / phases) + (slice & 3), slice >> 2);
}
// The sample (k, slice) at the march's texel t.
ivec2 sampleOfMarchTexel(ivec2 t) {
    int phases = int(epipolar.march.x);
    if (phases <= 1) return t;
    ivec2 size = ivec2(int(epipolar.sampling.y) / phases * 4, int(epipolar.sampling.x) / 4);
    ivec2 block = t / size, in_ = t % size;
    int r = block.y * int(epipolar.march.y) + block.x;
    return ivec2((in_.x >> 2) * phases + r, in_.y * 4 + (in_.x & 3));
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
