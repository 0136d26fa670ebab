// Camera rays: direction through a point of the screen, camera-space z from the depth buffer, and
// the sky's distance (docs/model.md, "Conventions at the edges").
#ifndef LS_CAMERA_GLSL
#define LS_CAMERA_GLSL
#include "frame.glsl"

// Unit direction of the ray through an NDC position.
vec3 rayDirection(vec2 ndc) {
    return normalize(ndc.x * frame.rayBasis[0].xyz + ndc.y * frame.rayBasis[1].xyz + frame.rayBasis[2].xyz);
}

vec2 pixelToNdc(vec2 pixelCenter) { return pixelCenter * frame.screenSize.zw * 2.0 - 1.0; }
vec2 ndcToPixel(vec2 ndc) { return (ndc * 0.5 + 0.5) * frame.screenSize.xy; }

// Unit direction of the ray through a pixel's centre.
vec3 pixelRayDirection(ivec2 pixel) { return rayDirection(pixelToNdc(vec2(pixel) + 0.5)); }

// S: the distance along unit ray v to its end, whose camera-space z is z (pixelCameraZ). The
// floor keeps rays at right angles to the view axis finite.
float rayLength(float z, vec3 v) { return z / max(dot(v, frame.cameraForward.xyz), 1e-4); }

bool isSkyDepth(float d) {
    bool reversed = frame.depthInfo.x > 0.5;
    return isnan(d) || (reversed ? d <= 0.0 : d >= 1.0);
}

// Camera-space z (positive distance along the view axis) of a depth-buffer value.
float depthToCameraZ(float d) {
    float n = frame.depthInfo.z, f = frame.depthInfo.w;
    bool reversed = frame.depthInfo.x > 0.5, infinite = frame.depthInfo.y > 0.5;
    if (infinite) return reversed ? n / d : n / (1.0 - d);
    return reversed ? n * f / (n + d * (f - n)) : n * f / (f - d * (f - n));
}

// Where a pixel's ray ends, as camera-space z: its surface, or for the sky the point at
// min(far-plane distance, maxDistance) (maxDistance alone with an infinite far plane). NaN depth
// counts as sky. cosAxis is dot(ray, view axis).
float rayEndCameraZ(float depth, float cosAxis) {
    float c = max(cosAxis, 1e-4);
    if (!isSkyDepth(depth)) return depthToCameraZ(clamp(depth, 0.0, 1.0));
    float sky = frame.betaM.w;
    if (frame.depthInfo.y < 0.5) sky = min(frame.depthInfo.w / c, sky);
    return sky * c;
}

// Camera-space z of the end of a pixel's ray, from the engine's depth buffer. No screen-sized
// texture of it is kept: each reader derives it where it reads the depth.
float pixelCameraZ(sampler2D depthBuffer, ivec2 pixel) {
    return rayEndCameraZ(texelFetch(depthBuffer, pixel, 0).r, dot(pixelRayDirection(pixel), frame.cameraForward.xyz));
}

#endif
