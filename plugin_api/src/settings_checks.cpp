#include "settings_checks.h"

#include "field_checks.h"
#include "shared/scattering_params.h"

namespace lightscatter::detail {

Settings mergedSettings(Profile profile, const Settings& custom) {
    // Everything is the engine's (custom) but what the profile decides: a field added to Settings
    // is the engine's without a word here.
    return profile == Profile::Custom ? custom : withProfileSizes(custom, profile);
}

void checkSettings(const Settings& s, const std::string& at) {
    const std::string c = at + ".";
    if (s.slices == 0 || s.slices % 4 != 0 || s.slices > 16384)
        fail(c + "slices = " + std::to_string(s.slices) +
             ": must be a positive multiple of 4 (a quarter per screen edge), at most 16384");
    if (s.samplesPerSlice < 2 || s.samplesPerSlice > 16384)
        fail(c + "samplesPerSlice = " + std::to_string(s.samplesPerSlice) +
             ": must be between 2 and 16384");
    const uint32_t st = s.initialSampleStep;
    if (st == 0 || (st & (st - 1)) != 0 || st > 128)
        fail(c + "initialSampleStep = " + std::to_string(st) +
             ": must be a power of two between 1 and 128");
    if (!(s.refinementThreshold > 0.0f) || !finite(s.refinementThreshold))
        fail(c + "refinementThreshold = " + num(s.refinementThreshold) + ": must be > 0");
    if (!(s.inscatterRefinementThreshold >= 0.0f) || !finite(s.inscatterRefinementThreshold))
        fail(c + "inscatterRefinementThreshold = " + num(s.inscatterRefinementThreshold) +
             ": must be finite and >= 0 (0: off)");
    if (!(s.bilateralThreshold > 0.0f) || !finite(s.bilateralThreshold))
        fail(c + "bilateralThreshold = " + num(s.bilateralThreshold) + ": must be > 0");
    inRange(s.shadowDepthBias, c + "shadowDepthBias", -1.0, 1.0,
            "the depth range: beyond it every ray is lit, or shadowed, all the same");
    if (s.coneSamples < 1 || s.coneSamples > 4096)
        fail(c + "coneSamples = " + std::to_string(s.coneSamples) + ": must be between 1 and 4096");
    if (s.froxelTile < 2 || s.froxelTile > 64)
        fail(c + "froxelTile = " + std::to_string(s.froxelTile) +
             ": must be between 2 and 64 pixels");
    if (s.froxelSlices < 4 || s.froxelSlices > 512)
        fail(c + "froxelSlices = " + std::to_string(s.froxelSlices) +
             ": must be between 4 and 512");
    inRange(s.froxelHistoryWeight, c + "froxelHistoryWeight", 0.0, 0.99,
            "the history's share of each froxel; 1 would never take a new frame");
    if (s.froxelFarDistance != 0.0f)
        inRange(s.froxelFarDistance, c + "froxelFarDistance", 1e-6, limits::kMaxLength,
                "or 0: the medium's maxDistance");
    if (s.planeCount < 2 || s.planeCount > 4096)
        fail(c + "planeCount = " + std::to_string(s.planeCount) + ": must be between 2 and 4096");
    if (s.planeSpacing != 0.0f)
        inRange(s.planeSpacing, c + "planeSpacing", 1e-6, limits::kMaxLength,
                "metres between sampling planes, or 0: planeCount planes");
    if (s.planeTarget != PlaneTarget::Float16 && s.planeTarget != PlaneTarget::Float32 &&
        s.planeTarget != PlaneTarget::Rgba8Channels)
        fail(c + "planeTarget is not a PlaneTarget value");
    if (s.planeRange != 0.0f)
        inRange(s.planeRange, c + "planeRange", 1e-30, 1e30,
                "or 0: automatic; the 8-bit target is scaled by 4 / planeRange");
    if (s.planeBlur > 8)
        fail(c + "planeBlur = " + std::to_string(s.planeBlur) + ": at most 8 pixels");
    inRange(s.planeAmbient, c + "planeAmbient", 0.0, limits::kMaxAmbient,
            "1/m^2, beside the inverse square; lightscatter.h, limits::kMaxAmbient");
    if (!(s.noiseAmplitude >= 0.0f && s.noiseAmplitude <= 1.0f))
        fail(c + "noiseAmplitude = " + num(s.noiseAmplitude) + ": must be in [0, 1]");
    inRange(s.noiseScale, c + "noiseScale", limits::kMinNoiseScale, limits::kMaxNoiseScale,
            "a tile's size; lightscatter.h, limits::kMinNoiseScale");
    for (size_t i = 0; i < s.noiseVelocity.size(); ++i)
        if (!finite(s.noiseVelocity[i]))
            fail(c + "noiseVelocity[" + std::to_string(i) + "] is not finite");
    if (s.lightModel != LightModel::Full && s.lightModel != LightModel::Simplified)
        fail(c + "lightModel is not a LightModel value");
    inRange(s.simplifiedA1, c + "simplifiedA1", limits::kMinSimplifiedA1, limits::kMaxSimplifiedA1,
            "seed 004's falloff I / (a1 r^2 + a0); lightscatter.h, limits::kMinSimplifiedA1");
    inRange(s.simplifiedA0, c + "simplifiedA0", 0.0, limits::kMaxSimplifiedA0,
            "m^2, seed 004's falloff I / (a1 r^2 + a0); lightscatter.h, limits::kMaxSimplifiedA0");
}

void applySettings(ls::LightSetup& s, const Settings& st, uint32_t shadowMapSize) {
    s.epipolar.slices = st.slices;
    s.epipolar.samples = st.samplesPerSlice;
    s.epipolar.initialStep = st.initialSampleStep;
    s.epipolar.refinementThreshold = st.refinementThreshold;
    s.epipolar.inscatterRefinementThreshold = st.inscatterRefinementThreshold;
    s.epipolar.bilateralThreshold = st.bilateralThreshold;
    s.epipolar.minMaxTrees = st.minMaxTrees && ls::treesFit(shadowMapSize);
    s.epipolar.bilinearShadow = st.shadowFilter == ShadowFilter::Bilinear;
    s.epipolar.fixup = st.fixup;
    s.epipolar.fixupMaxSteps = st.fixupMaxSteps;
    s.epipolar.shadowDepthBias = st.shadowDepthBias;
    s.epipolar.interpolateFraction = st.interpolation == Interpolation::ShadowedFraction;
    s.planes.planes = st.planeCount;
    s.planes.spacing = st.planeSpacing;
    s.planes.planeScaling = st.planeScaling;
    s.planes.eightBitTarget = st.planeTarget == PlaneTarget::Rgba8Channels;
    s.planes.range = st.planeRange;
    s.planes.ambient = st.planeAmbient;
    s.planes.noiseAmplitude = st.noiseAmplitude;
    s.planes.noiseScale = st.noiseScale;
    s.planes.noiseVelocity = {st.noiseVelocity[0], st.noiseVelocity[1], st.noiseVelocity[2],
                              st.noiseVelocity[3]};
    s.planeTarget = st.planeTarget;
    s.planeBlur = st.planeBlur;
    s.planeDither = st.planeDither;
    s.cone = {st.coneSamples, st.coneLimited, st.coneJitter};
    s.froxels = {st.froxelTile, st.froxelSlices, st.froxelFarDistance, st.froxelTemporal,
                 st.froxelHistoryWeight};
    s.shadowSampling = st.shadowSampling;
    s.noise = st.noiseAmplitude > 0.0f;
    s.simplified = st.lightModel == LightModel::Simplified;
}

}  // namespace lightscatter::detail
