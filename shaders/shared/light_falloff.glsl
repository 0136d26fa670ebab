// A point or spot light's smooth edges (docs/model.md, "The lights"): a spot's angular falloff
// between its inner and outer cones and the range window, both KHR_lights_punctual's. The hard
// ones (a hard cone edge, a range that cuts) are the light's volume, which light_volume.glsl clips
// rays to; these multiply the irradiance inside it.
#ifndef LS_LIGHT_FALLOFF_GLSL
#define LS_LIGHT_FALLOFF_GLSL
#include "frame.glsl"

// Whether the light has a smooth edge at all: a frame without one multiplies by nothing.
bool smoothFalloff() {
    return kLightType != LIGHT_DIRECTIONAL &&
           ((kLightType == LIGHT_SPOT && frame.lightFalloff.y > 0.0) || frame.lightFalloff.z > 0.0);
}

// The falloff at P: a = clamp((cos t - cos outer) / (cos inner - cos outer), 0, 1)^2 for a spot,
// times w = clamp(1 - (d / range)^4, 0, 1) for a windowed range, d = |P - L|.
float lightFalloff(vec3 P) {
    vec3 fromLight = P - frame.lightPos.xyz;
    float d = length(fromLight);
    float f = 1.0;
    if (kLightType == LIGHT_SPOT && frame.lightFalloff.y > 0.0) {
        float c = d > 0.0 ? dot(fromLight / d, frame.lightDir.xyz) : 1.0;
        float a = clamp((c - frame.lightDir.w) * frame.lightFalloff.y, 0.0, 1.0);
        f = a * a;
    }
    if (frame.lightFalloff.z > 0.0) {
        float q = d / frame.lightIntensity.w;
        q *= q;
        f *= clamp(1.0 - q * q, 0.0, 1.0);
    }
    return f;
}

// How long a piece of a ray at distance h from the light may be for the falloff at its middle to
// stand for it (0: no smooth falloff, one piece): at least 8 pieces across the spot's penumbra
// (lightFalloff.w, its angular width) seen from the ray, and 32 across the range.
float falloffPiece(float h) {
    if (!smoothFalloff()) return 0.0;
    float piece = 1e30;
    if (kLightType == LIGHT_SPOT && frame.lightFalloff.y > 0.0)
        piece = max(h, frame.betaT.w) * frame.lightFalloff.w / 8.0;
    if (frame.lightFalloff.z > 0.0) piece = min(piece, frame.lightIntensity.w / 32.0);
    return piece;
}

// How many pieces of at most `piece` cover `length` (at most 64).
int falloffPieces(float length, float piece) {
    return int(clamp(ceil(length / piece), 1.0, 64.0));
}

#endif
