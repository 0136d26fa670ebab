#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform sampler2D source;
// Specialisation constant 0: invert the color (used inside the stencil mask).
layout(constant_id = 0) const bool kInvert = false;

void main() {
    vec4 c = texelFetch(source, ivec2(gl_FragCoord.xy), 0);
    color = kInvert ? vec4(1.0 - c.rgb, 1.0) : c;
}
