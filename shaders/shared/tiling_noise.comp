#version 450
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
// The plugin's own tiling noise for seed 002's density noise: two independent layers (red, green)
// of four-octave value noise whose lattices wrap at the image's edge, so that the image repeats
// without a seam. Each layer is rescaled to mean 1/2 over [0, 1].
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = LS_BINDING_NOISE_OUT, rg8) uniform writeonly image2D noiseOut;

float hash(uvec2 p, uint seed) {
    uint h = p.x * 0x8da6b343u ^ p.y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return float(h >> 8) / 16777216.0;
}

// Value noise with `cells` lattice cells across the image, wrapping.
float valueNoise(vec2 uv, uint cells, uint seed) {
    vec2 p = uv * float(cells);
    uvec2 i = uvec2(floor(p));
    vec2 f = fract(p);
    f = f * f * (3.0 - 2.0 * f);
    uvec2 i1 = (i + 1u) % cells;
    i %= cells;
    float a = hash(i, seed), b = hash(uvec2(i1.x, i.y), seed);
    float c = hash(uvec2(i.x, i1.y), seed), d = hash(i1, seed);
    return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}

float layer(vec2 uv, uint seed) {
    float sum = 0.0, amplitude = 0.5, total = 0.0;
    for (uint o = 0u; o < 4u; ++o) {
        sum += amplitude * valueNoise(uv, 4u << o, seed + o);
        total += amplitude;
        amplitude *= 0.5;
    }
    return sum / total;
}

void main() {
    ivec2 size = imageSize(noiseOut);
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, size))) return;
    vec2 uv = (vec2(p) + 0.5) / vec2(size);
    imageStore(noiseOut, p, vec4(layer(uv, 1u), layer(uv, 101u), 0.0, 0.0));
}
