#pragma once
// Epipolar sampling's own settings (seed 000), Settings::epipolar: every choice the seed leaves
// open. Their ranges, defaults and one line of doc each are the method's field table
// (lightscatter::settingsFields(), names "epipolar.*"), which the plugin checks a frame against.
// A "slice" here is an epipolar line: the samples of one line from the light across the screen.
#include <cstdint>

namespace lightscatter {

// What epipolar samples carry between ray marching and the screen. Seed 000 interpolates Lin
// itself; interpolating the shadowed fraction of the closed-form unshadowed Lin instead keeps the
// glow around a light (which no sparse sampling resolves) exact, and changes nothing where there is
// no glow.
enum class Interpolation { ShadowedFraction, Inscattering };

struct EpipolarSettings {
    uint32_t slices = 1024;             // epipolar lines; a multiple of 4 (one quarter per edge)
    uint32_t samplesPerSlice = 1024;    // samples along each line
    uint32_t initialSampleStep = 16;    // ray-marching samples every N samples (a power of two)
    float refinementThreshold = 0.03f;  // relative camera-z jump that is a depth break
    // Refinement on what the samples carry (docs/epipolar.md, "Refinement on in-scattering
    // differences"). 0 (the default): off. Above 0: after the first march, wherever the two
    // ray-marching samples an interpolated sample lies between differ in some channel by more than
    // this fraction of the larger (the shadowed fraction, or Lin with Interpolation::Inscattering),
    // or one carries light and the other none, every sample between them is marched too (a second,
    // stencil-limited march), so a shadow edge no depth break marks is not interpolated across.
    float inscatterRefinementThreshold = 0.0f;
    float bilateralThreshold = 0.1f;  // relative camera-z difference accepted when unwarping
    bool minMaxTrees = true;          // 1D min/max binary trees per slice
    bool fixup = true;                // ray-march pixels the unwarp cannot interpolate
    uint32_t fixupMaxSteps = 0;       // 0: every shadow-map texel; else at most this many
    Interpolation interpolation = Interpolation::ShadowedFraction;
};

}  // namespace lightscatter
