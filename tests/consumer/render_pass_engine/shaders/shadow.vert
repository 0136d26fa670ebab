#version 450
// Depth only: the spot's shadow map (no fragment shader).
#extension GL_GOOGLE_include_directive : require
#include "scene.glsl"
layout(location = 0) in vec3 inPosition;
void main() {
    gl_Position = frame.lightViewProjection * vec4(inPosition, 1.0);
}
