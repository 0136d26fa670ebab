#version 450
#extension GL_GOOGLE_include_directive : require
// Sample refinement (seed 000): ray-marching samples every `initial step` samples, plus the samples
// on both sides of every depth break; every other sample is interpolated from the nearest
// ray-marching sample on each side. One workgroup covers 128 samples of one slice: each thread sets a
// bit per break in shared memory, then finds its two sources with findMSB/findLSB on the masks.
// Near a point or spot light's screen position the first section of each line is cut geometrically
// (below). With the march list (marchesFromList), each ray-marching sample of the march order's
// tiles also takes the list's next slot: one atomic add per such sample (a few percent of the
// samples), which kept this pass's time where it was on lavapipe, where a workgroup's slots
// reserved at once, behind two more barriers, made it 1.8 times slower.
#include "epipolar_constants.glsl"
#include "frame.glsl"
#include "epipolar_bindings.h"
layout(local_size_x = 128) in;
layout(binding = LS_BINDING_REFINE_EPIPOLAR_Z) uniform sampler2D epipolarZ;
layout(binding = LS_BINDING_REFINE_SOURCES, rg16ui) uniform writeonly uimage2D interpolationSource;
// The march list (marchesFromList in epipolar_constants.glsl), its count cleared before this pass.
layout(std430, binding = LS_BINDING_REFINE_LIST) buffer MarchList {
    uint count;
    uint entries[];
} marchList;

shared uint breaks[4];  // bit k: break between local samples k and k+1

// Highest set bit in local range [lo, hi], or -1.
int highestBreak(int lo, int hi) {
    for (int w = hi >> 5; w >= (lo >> 5) && w >= 0; --w) {
        uint m = breaks[w];
        int a = max(lo - w * 32, 0), b = min(hi - w * 32, 31);
        if (a > b) continue;
        m &= (b == 31 ? 0xffffffffu : ((1u << (b + 1)) - 1u)) & ~((1u << a) - 1u);
        if (m != 0u) return w * 32 + findMSB(m);
    }
    return -1;
}

// Lowest set bit in local range [lo, hi], or -1.
int lowestBreak(int lo, int hi) {
    for (int w = lo >> 5; w <= (hi >> 5) && w < 4; ++w) {
        uint m = breaks[w];
        int a = max(lo - w * 32, 0), b = min(hi - w * 32, 31);
        if (a > b) continue;
        m &= (b == 31 ? 0xffffffffu : ((1u << (b + 1)) - 1u)) & ~((1u << a) - 1u);
        if (m != 0u) return w * 32 + findLSB(m);
    }
    return -1;
}

// Stores sample s's interpolation sources; true for a ray-marching sample of the march list's.
bool refine(int s, int local, int base, int slice, int samples, int step, bool valid, bool brk) {
    int last = samples - 1;
    int sectionStart = (local / step) * step;
    int sectionEnd = min(sectionStart + step, last - base);  // local index, may be 128 (next group)
    // A point or spot light on screen: every line starts at it, and there a sample's ray passes
    // the light at a distance proportional to the sample's index. What the sample carries is
    // decided near that closest approach, within about that distance of the light: near the light
    // it changes over a few samples, further out over many (a cage around the light, seen from
    // outside, is a ring of shadows a few pixels across). The first section of such a line is cut
    // at samples 1, 2, 4, ..., so that the ray-marching samples there are spaced like their
    // distance from the light (log2(initial step) more per line); a sun has no such scale.
    if (kLightType != LIGHT_DIRECTIONAL && frame.lightScreen.w > 0.5 && base == 0 && local < step) {
        sectionStart = local == 0 ? 0 : 1 << findMSB(local);
        sectionEnd = min(max(2 * sectionStart, 1), sectionEnd);
    }
    bool breakAfter = brk;
    bool breakBefore = local > 0 ? ((breaks[(local - 1) >> 5] >> ((local - 1) & 31)) & 1u) != 0u
                                 : true;
    uvec2 src;
    if (local == sectionStart || s == last || breakAfter || breakBefore || !valid) {
        src = uvec2(s);  // a ray-marching sample: interpolated from itself
    } else {
        int lo = highestBreak(sectionStart, local - 1);
        int hi = lowestBreak(local, min(sectionEnd, 128) - 1);
        src = uvec2(base + (lo >= 0 ? lo + 1 : sectionStart), base + (hi >= 0 ? hi : sectionEnd));
    }
    imageStore(interpolationSource, ivec2(s, slice), uvec4(src, 0u, 0u));
    return src.x == uint(s) && src.y == uint(s) && valid && marchesFromList() && inMarchTiles(s);
}

void main() {
    int local = int(gl_LocalInvocationID.x);
    int base = int(gl_WorkGroupID.x) * 128;
    int slice = int(gl_WorkGroupID.y);
    int samples = int(epipolar.sampling.y);
    int step = int(epipolar.sampling.z);
    int s = base + local;
    if (local < 4) breaks[local] = 0u;
    barrier();

    float z = s < samples ? texelFetch(epipolarZ, ivec2(s, slice), 0).r : -1.0;
    float zNext = s + 1 < samples ? texelFetch(epipolarZ, ivec2(s + 1, slice), 0).r : -1.0;
    bool valid = validSampleZ(z), validNext = validSampleZ(zNext);
    // A change of validity is a break too, so no sample interpolates from outside the screen.
    bool brk = valid != validNext ||
               (valid && abs(zNext - z) > epipolar.sampling.w * min(z, zNext));
    if (brk) atomicOr(breaks[local >> 5], 1u << (local & 31));
    barrier();
    if (s >= samples) return;
    if (refine(s, local, base, slice, samples, step, valid, brk)) {
        // Counted past the list's end too: the march then finds the list overflowed.
        uint slot = atomicAdd(marchList.count, 1u);
        if (slot < uint(marchListCapacity(findLSB(int(epipolar.march.x)))))
            marchList.entries[slot] = marchListEntry(ivec2(s, slice));
    }
}
