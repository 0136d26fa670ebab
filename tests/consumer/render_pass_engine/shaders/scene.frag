#version 450
// Forward shading, no units: albedo * (ambient + N.L * spot cone * shadow), written linear into the
// sRGB target (the hardware encodes).
#extension GL_GOOGLE_include_directive : require
#include "scene.glsl"
layout(set = 0, binding = 1) uniform sampler2DShadow shadowMap;
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColor;
layout(location = 0) out vec4 outColor;

float shadow(vec3 position) {
    vec4 clip = frame.lightViewProjection * vec4(position, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    if (clip.w <= 0.0 || any(greaterThan(abs(ndc.xy), vec2(1.0)))) return 0.0;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    // 3x3 PCF.
    vec2 texel = 1.0 / vec2(textureSize(shadowMap, 0));
    float lit = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) lit += texture(shadowMap, vec3(uv + vec2(x, y) * texel, ndc.z));
    return lit / 9.0;
}

void main() {
    vec3 toLight = frame.lightPosition.xyz - inPosition;
    vec3 l = normalize(toLight);
    float cosAngle = dot(-l, frame.lightDirection.xyz);
    float cone = smoothstep(frame.lightDirection.w, frame.lightPosition.w, cosAngle);
    float nDotL = max(dot(normalize(inNormal), l), 0.0);
    vec3 light = frame.lightColor.rgb * nDotL * cone * shadow(inPosition);
    outColor = vec4(inColor * (frame.lightColor.w + light), 1.0);
}
