#version 450
#extension GL_GOOGLE_include_directive : require
// The epipolar ray march's order (marchTexel, sampleOfMarchTexel, marchListSlot in
// epipolar_constants.glsl) as the passes evaluate it, written out for
// tests/passes/epipolar_march_order_gpu_test.cpp: the texel of every sample, the sample of every
// texel of the march's extent (x | y << 16), and what the march takes at each texel given the march
// list's count: its slot of the list, or ~0 and the sample it marches itself.
#include "epipolar_constants.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) writeonly buffer TexelOfSample { uint texelOf[]; };
layout(std430, binding = 1) writeonly buffer SampleOfTexel { uint sampleOf[]; };
layout(std430, binding = 2) writeonly buffer SlotOfTexel { uint slotOf[]; };
layout(std430, binding = 3) writeonly buffer MarchedAtTexel { uint marchedAt[]; };
// The march's extent, and the list's count the march reads.
layout(push_constant) uniform Push { uint width, height, count; } pc;

uint pack(ivec2 p) { return (uint(p.x) & 0xffffu) | (uint(p.y) << 16); }

void main() {
    uint i = gl_GlobalInvocationID.x;
    uint samples = uint(epipolar.sampling.y), slices = uint(epipolar.sampling.x);
    if (i < samples * slices) texelOf[i] = pack(marchTexel(int(i % samples), int(i / samples)));
    if (i < pc.width * pc.height) {
        ivec2 t = ivec2(i % pc.width, i / pc.width), at;
        sampleOf[i] = pack(sampleOfMarchTexel(t));
        int slot = marchListSlot(t, pc.count, at);
        slotOf[i] = slot >= 0 ? uint(slot) : ~0u;
        marchedAt[i] = slot >= 0 ? ~0u : pack(at);
    }
}
