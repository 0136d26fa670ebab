#version 450
#extension GL_GOOGLE_include_directive : require
// The epipolar ray march's order (marchTexel, sampleOfMarchTexel in epipolar_constants.glsl) as
// the passes evaluate it, written out for tests/passes/epipolar_march_order_gpu_test.cpp: the texel
// of every sample, and the sample of every texel of the march's extent, each packed x | y << 16.
#include "epipolar_constants.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) writeonly buffer TexelOfSample { uint texelOf[]; };
layout(std430, binding = 1) writeonly buffer SampleOfTexel { uint sampleOf[]; };
layout(push_constant) uniform Push { uint width, height; } pc;  // the march's extent

uint pack(ivec2 p) { return (uint(p.x) & 0xffffu) | (uint(p.y) << 16); }

void main() {
    uint i = gl_GlobalInvocationID.x;
    uint samples = uint(epipolar.sampling.y), slices = uint(epipolar.sampling.x);
    if (i < samples * slices) texelOf[i] = pack(marchTexel(int(i % samples), int(i / samples)));
    if (i < pc.width * pc.height)
        sampleOf[i] = pack(sampleOfMarchTexel(ivec2(i % pc.width, i / pc.width)));
}
