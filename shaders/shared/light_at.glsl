// What reaches one point of a camera ray from the light: the irradiance of docs/model.md (with the
// light's extinction on the way, the spot's cone and range), times shadow-map visibility and the
// light color when the including shader has them, and the cosine of the scattering angle. Used by
// the methods that sample the integrand at points (cone-march, planes, the beam-tree methods'
// sampling planes). With kSimplifiedModel (seed 004's light model, simplified.glsl) the irradiance
// is I / (a1 r^2 + a0) without extinction, and towardCamera() drops the transmittance to the camera
// and the phase function's shape: a shader that samples the integrand as
// towardCamera(s, cosTheta) * lightAt(...) honours either model.
// The including shader defines LS_SHADOW_MAP and LS_LIGHT_COLOR (0 or 1), declares `shadowMap` and
// includes shadow.glsl when LS_SHADOW_MAP, and includes light_color.glsl.
#ifndef LS_LIGHT_AT_GLSL
#define LS_LIGHT_AT_GLSL
#include "frame.glsl"
#include "light_falloff.glsl"
#include "math.glsl"
#include "medium.glsl"
#include "simplified.glsl"

// Multiplies f by the shadow map's visibility and the light color at P, where the including
// shader has them: lightAt's factors beside the irradiance.
void applyShadowAndColor(vec3 P, inout vec3 f) {
#if LS_SHADOW_MAP || LS_LIGHT_COLOR
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
    // A point light's cube map: the face of P - L's major axis (+X, -X, +Y, -Y, +Z, -Z), whose
    // layer the look-up reads (a point on a seam takes either face: both maps see it).
    vec3 fromLight = P - frame.lightPos.xyz, m = abs(fromLight);
    shadowFace = m.x >= m.y && m.x >= m.z ? (fromLight.x >= 0.0 ? 0 : 1)
               : m.y >= m.z               ? (fromLight.y >= 0.0 ? 2 : 3)
                                          : (fromLight.z >= 0.0 ? 4 : 5);
    vec4 X = frame.cubeFaceViewProj[shadowFace] * vec4(P, 1.0);
#else
    vec4 X = frame.lightViewProj * vec4(P, 1.0);
#endif
    if (X.w > 0.0) {
        vec2 uv = X.xy / X.w * 0.5 + 0.5;
#if LS_SHADOW_MAP
        f *= shadowVisibility(uv, toStandardDepth(X.z / X.w));
#endif
        f *= lightColorAt(uv);
    }
#endif
}

// `ambient` (1/m^2, point and spot lights): seed 002's term beside the inverse square; 0 is the model.
vec3 lightAt(vec3 P, vec3 v, float ambient, out float cosTheta) {
    vec3 irr;
    if (kLightType == LIGHT_DIRECTIONAL) {
        cosTheta = dot(v, -frame.lightDir.xyz);
        irr = frame.lightIntensity.rgb;
    } else {
        vec3 toLight = frame.lightPos.xyz - P;
        float r = length(toLight);
        vec3 l = r > 0.0 ? toLight / r : -frame.lightDir.xyz;
        cosTheta = dot(v, l);
        if (kSimplifiedModel) {
            irr = frame.lightIntensity.rgb * (simplifiedFalloff(r * r) + ambient);
        } else {
            float r0 = frame.betaT.w;
            // The light's path: r of the medium, or its optical depth in a non-uniform one.
            float depth = kMedia != 0 ? opticalDepthTo(P, frame.lightPos.xyz) : r;
            irr = frame.lightIntensity.rgb * exp(-frame.betaT.rgb * depth) * (1.0 / (r * r + r0 * r0) + ambient);
        }
        if (kLightType == LIGHT_SPOT && dot(-l, frame.lightDir.xyz) < frame.lightDir.w)
            return vec3(0.0);                              // outside the cone
        if (r > frame.lightIntensity.w) return vec3(0.0);  // beyond the range
        if (smoothFalloff()) irr *= lightFalloff(P);
    }
    applyShadowAndColor(P, irr);
    return irr;
}

// What a point at distance s from the camera sends to it per unit length and unit irradiance, the
// scattering angle's cosine being cosTheta: exp(-betaT s) P(t) of docs/model.md, or seed 004's
// betaS / (4 pi) with kSimplifiedModel.
vec3 towardCamera(float s, float cosTheta) {
    if (kSimplifiedModel) return (frame.betaR.rgb + frame.betaM.rgb) / (4.0 * PI);
    return exp(-frame.betaT.rgb * s) * phaseSum(cosTheta);
}

// The same for the point P at distance s along the camera ray in any medium: m(P) T(s) P(t), with
// T of the optical depth from the camera (a non-uniform medium's), or towardCamera's.
vec3 towardCameraFrom(vec3 P, float s, float cosTheta) {
    if (kMedia == 0 || kSimplifiedModel) return towardCamera(s, cosTheta);
    vec3 C = frame.cameraPos.xyz;
    float tau = s > 0.0 ? opticalDepth(C, (P - C) / s, s) : 0.0;
    return densityAt(P) * exp(-frame.betaT.rgb * tau) * phaseSum(cosTheta);
}

#endif
