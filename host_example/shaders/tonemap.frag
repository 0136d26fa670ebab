#version 450
// The window's display: exposure, an ACES fit (Narkowicz 2015) and the swapchain's sRGB encoding.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 outColor;
layout(binding = 0) uniform sampler2D hdr;
layout(push_constant) uniform Push { float exposure; } pc;

vec3 aces(vec3 x) {
    // The fit reaches 1 at x = 7.24; clamping first keeps x * (2.51 x + 0.03) from overflowing
    // (from about 1.2e19, and for +Inf from a half-float target), where inf / inf made it black.
    x = min(x, vec3(64.0));
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void main() {
    vec3 c = texelFetch(hdr, ivec2(gl_FragCoord.xy), 0).rgb * pc.exposure;
    // NaN compares false: it shows as black, as on the command line's PNGs.
    c = mix(vec3(0.0), c, greaterThan(c, vec3(0.0)));
    outColor = vec4(aces(c), 1.0);
}
