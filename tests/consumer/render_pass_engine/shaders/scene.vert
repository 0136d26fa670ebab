#version 450
#extension GL_GOOGLE_include_directive : require
#include "scene.glsl"
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColor;
layout(location = 0) out vec3 outPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outColor;
void main() {
    outPosition = inPosition;
    outNormal = inNormal;
    outColor = inColor;
    gl_Position = frame.viewProjection * vec4(inPosition, 1.0);
}
