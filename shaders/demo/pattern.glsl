// The test pattern, shared by the generating shader; tests recompute it on the CPU from this
// definition, so keep the two in step (tests/rendergraph/test_pattern_reference.cpp).
vec4 testPattern(uvec2 p, uvec2 size) {
    vec2 t = (vec2(p) + 0.5) / vec2(size);
    bool check = (((p.x >> 3) ^ (p.y >> 3)) & 1u) == 1u;
    return vec4(t.x, t.y, check ? 0.75 : 0.25, 1.0);
}

bool insideCircle(uvec2 p, uvec2 size) {
    vec2 c = vec2(size) * 0.5;
    vec2 d = vec2(p) + 0.5 - c;
    float r = 0.35 * float(min(size.x, size.y));
    return dot(d, d) < r * r;
}
