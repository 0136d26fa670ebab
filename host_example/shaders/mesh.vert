#version 450
// The host engine's meshes: world-space vertices (the loader flattened the hierarchy).
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 0) out vec3 worldPos;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec2 uv;
layout(push_constant) uniform Push {
    mat4 viewProj;
    vec4 baseColor;
} pc;

void main() {
    worldPos = inPosition;
    worldNormal = inNormal;
    uv = inUv;
    gl_Position = pc.viewProj * vec4(inPosition, 1.0);
}
