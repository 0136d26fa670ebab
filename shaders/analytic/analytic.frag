#version 450
#extension GL_GOOGLE_include_directive : require
// Seed 001: Lin of an unshadowed point or spot light in closed form, per pixel, for a medium that
// scatters isotropically and does not attenuate:
//     Lin = I betaS / (4 pi) * integral over [t0, t1] of ds / ((s + b)^2 + w^2)
// with q = C - L, b = dot(v, q), w^2 = |cross(v, q)|^2 + r0^2 (the light's radius keeps a ray
// through the light finite), and [t0, t1] the ray's part inside the spot's cone and range (all of
// [0, S] for a point light). The phase function's shape and the extinction are what it ignores
// (docs/methods.md measures what that costs). With kSimplifiedModel it is seed 004's simplified
// model (simplified.glsl), the same integral with a1, a0 in place of 1, r0^2: then exactly so.
#include "camera.glsl"
#include "light_volume.glsl"
#include "simplified.glsl"
layout(binding = LS_BINDING_DEPTH) uniform sampler2D depthBuffer;  // the engine's depth
layout(location = 0) out vec4 outInscatter;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 C = frame.cameraPos.xyz;
    vec3 v = pixelRayDirection(pixel);
    float S = rayLength(pixelCameraZ(depthBuffer, pixel), v);
    float t0, t1;
    lightInterval(C, v, S, t0, t1);
    vec3 lin = vec3(0.0);
    if (kSimplifiedModel) {
        lin = simplifiedInscatter(C, v, t0, t1);
    } else if (t0 < t1) {
        vec3 q = C - frame.lightPos.xyz;
        float b = dot(v, q);
        vec3 h = cross(v, q);  // never |q|^2 - b^2, which cancels
        float r0 = frame.betaT.w;
        float w = sqrt(dot(h, h) + r0 * r0);
        vec3 betaS = frame.betaR.rgb + frame.betaM.rgb;
        float integral = falloffArctanIntegral(C, v, t0, t1, b, w, length(h));
        lin = frame.lightIntensity.rgb * betaS * (integral / (4.0 * PI));
    }
    outInscatter = vec4(storedLin(lin), 1.0);
}
