#pragma once
// lightscatter::limits: the ranges of a frame's numbers (included by lightscatter.h).

namespace lightscatter {

// The ranges of a frame's numbers. The plugin computes in single precision: FLT_MAX is about
// 3.4e38, the smallest normal float 1.2e-38, and a GPU may flush smaller (subnormal) values to 0.
// Each numeric field's comment states its range (a Settings field's is in its field table,
// settingsFields()), and record() refuses a value outside it (InvalidInput naming the field and
// the range). The bounds are chosen so that no shader overflows: the largest product one forms is
// Lin's integrand times the length of ray it stands for,
//       intensity     1e9 W/sr or W/m^2           kMaxIntensity
//     x irradiance    2e6 1/m^2                   1 / r0^2 with r0 >= kMinRadius, plus planes'
//                                                 ambient term, at most kMaxAmbient
//     x coefficient   1e3 1/m                     kMaxCoefficient
//     x phase         2e5 1/sr                    Cornette-Shanks' peak, 0.16 / (1 - g)^2 under
//                                                 the shaders' floor of 1e-6 on its denominator,
//                                                 for any g in (-1, 1)
//     x length        6e9 m                       kMaxLength over the cosine of a ray at the
//                                                 corner of the widest field of view
//     = 2.4e33, a factor of 1e5 below FLT_MAX; a sum of samples along a ray is never more than
// its largest term times the ray's length. Seed 004's simplified model (Settings::lightModel)
// replaces the last three by betaS / (4 pi) <= 80 times the length, and 1 / r0^2 by its falloff,
// at most 1e12 / a1 <= 1e15 (the plugin floors a0 / a1 at 1e-12 m^2): 5e35, a factor of 600 below.
// Lower ends: a length or angle below its bound is one single precision cannot resolve (each
// bound says how); everything else may be 0 or subnormal, which renders as 0 would. A Lin below
// 6e-8 W/(m^2 sr), float16's smallest value, which the methods' screen targets hold, reads as 0
// (plugin_api/src/lin_storage.h scales a bright frame's Lin into float16's range).
namespace limits {
// Coordinates (light.position, the camera's position in camera.view), the far plane, the sky
// distance and the light's radius, in metres: 1e8 m, a quarter of the way to the Moon. Squares
// of distances (up to 4e19 between two points) stay far below FLT_MAX.
inline constexpr float kMaxLength = 1e8f;
// Light.intensity: W/m^2 (directional) or W/sr (point, spot). The Sun gives 1.4e3 W/m^2.
inline constexpr float kMaxIntensity = 1e9f;
// Medium::betaR, betaM, sigmaA, per channel, 1/m: a mean free path of a millimetre (milk is
// about 1e3 /m, thick fog 0.1 /m).
inline constexpr float kMaxCoefficient = 1e3f;
// Light::radius r0 (m): keeps 1 / (r^2 + r0^2) at most 1e6 /m^2.
inline constexpr float kMinRadius = 1e-3f;
// Settings::planes.ambient (1/m^2): no more than the inverse square at kMinRadius.
inline constexpr float kMaxAmbient = 1e6f;
// Light::innerConeAngleDegrees and outerConeAngleDegrees: the cone test compares cosines, whose
// float32 step near 1 (6e-8) moves the edge of a 0.1-degree cone by 2% of its angle and swallows
// cones under 0.02 degree whole.
inline constexpr float kMinConeAngleDegrees = 0.1f;
[[deprecated("use kMinConeAngleDegrees")]] inline constexpr float kMinHalfAngleDegrees = 0.1f;
// Settings::simplifiedA1 (a1 of I / (a1 r^2 + a0)): seed 004's a1 is 1; 1e-3 to 1e3 keeps its
// falloff within the budget above. simplifiedA0 (m^2) up to kMaxLength^2.
inline constexpr float kMinSimplifiedA1 = 1e-3f, kMaxSimplifiedA1 = 1e3f;
inline constexpr float kMaxSimplifiedA0 = 1e16f;
// Settings::noiseScale: a tile from 1e-6 (m, or the tangent of the angle it spans) to
// kMaxLength; noise coordinates (position / scale) stay below 1e14.
inline constexpr float kMinNoiseScale = 1e-6f, kMaxNoiseScale = 1e8f;
// The camera's field of view, on each axis (from camera.projection: 2 atan(1 / |P[0][0]|) and
// 2 atan(1 / |P[1][1]|)). Measured against the float64 model on 32x18 and 256x4 screens under an
// unshadowed sun (mean relative error of Lin): brute-force, epipolar and cone-march within 0.05%,
// planes within 2.4% (its planes' sampling), from 1e-6 degrees to 177 across; below 1e-7 degrees
// the planes degenerate (0.87 off), and at 178.9 degrees across every method is 9% off. 1e-4
// degrees keeps a margin of 100, and spans 29 float32 steps of a unit vector's component.
// tests/plugin/camera_limits_gpu_test.cpp holds the ends.
inline constexpr float kMinFovDegrees = 1e-4f, kMaxFovDegrees = 177.0f;
// The near plane (m). A reversed float32 depth buffer stores near / distance, a normal float out
// to kMaxLength for a near plane down to 1e-29 m. Measured on a 32x18 spot against the float64
// model: with reversed depth, finite or infinite, every method's error at near 1e-30 m is its
// error at 1e-4 m (brute-force 0.0003, planes 0.064).
inline constexpr float kMinNearPlane = 1e-29f;
// Standard depth (near plane at 0) and 16- or 24-bit depth formats either way round step by 2^-b
// (b = 24 bits for D24 and, near 1, for D32_SFLOAT; 16 for D16): at distance z the step is z^2 /
// near 2^-b. The far plane (with an infinite one: the sky distance, Medium::maxDistance) may be
// at most 2^b / 16 times the near plane, where one step is 1/16 of the distance; beyond 2^b the
// far part of the view collapses onto depth 1 and reads as sky. Reversed depth in D32_SFLOAT has
// no such limit.
inline constexpr float kDepthStepsPerDistance = 16.0f;
// FrameDescription::preExposure: the bound above leaves Lin a factor of 1e5 below FLT_MAX; an
// exposure of up to 1e4 keeps a factor of 10.
inline constexpr float kMaxPreExposure = 1e4f;
// Medium::fogVolumes: each volume is a loop iteration of every sample's density and of every
// optical depth a method takes (the volumes outside the view and the light's reach are dropped
// before the shaders see them), and the frame's constants hold them all.
inline constexpr unsigned kMaxFogVolumes = 64;
// Medium::density and FogVolume::density: a multiplier of the coefficients, at most 1e3 (the
// densest point's coefficients are held to kMaxCoefficient as a whole).
inline constexpr float kMaxDensity = 1e3f;
// HeightFog::falloff (1/m): 1e4 is a layer whose density halves over 0.07 mm.
inline constexpr float kMaxFogFalloff = 1e4f;
}  // namespace limits

}  // namespace lightscatter
