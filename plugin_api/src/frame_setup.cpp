#include "frame_setup.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "camera_checks.h"
#include "cube_face_checks.h"
#include "field_checks.h"
#include "image_checks.h"
#include "matrix_checks.h"
#include "rendergraph/format_info.h"

namespace lightscatter::detail {

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

Settings mergedSettings(Profile profile, const Settings& custom) {
    // Everything is the engine's (custom) but what the profile decides: a field added to Settings
    // is the engine's without a word here.
    return profile == Profile::Custom ? custom : withProfileSizes(custom, profile);
}

FrameSetup setupFrameWide(const FrameDescription& f, bool withImages) {
    FrameSetup s;
    s.settings = mergedSettings(f.profile, f.custom);
    checkSettings(s.settings);
    // Checked, and converted, only for the methods that read them (beamOccluders): the others
    // ignore them, as the header says, and a scene of 100,000 parts must not stop them.
    s.occluders = f.occluders.size();
    if (!std::isfinite(f.timeSeconds))
        fail("timeSeconds = " + num(f.timeSeconds) + ": must be finite");
    s.timeSeconds = f.timeSeconds;
    if (!(f.preExposure >= 0.0f && f.preExposure <= limits::kMaxPreExposure))
        fail("preExposure = " + num(f.preExposure) + ": must be in [0, " +
             num(limits::kMaxPreExposure) + "] (lightscatter.h, limits::kMaxPreExposure)");
    s.preExposure = f.preExposure;

    // Camera.
    s.camera = setupCamera(f.camera);
    // What the depth buffer can resolve, before anything that a near plane too small for it
    // would break (the depth format is the engine's image's: unknown to the budget).
    if (withImages && rg::hasDepth(f.depth.format) && f.medium.maxDistance > 0.0f)
        checkDepthResolution(s.camera, f.medium.maxDistance, f.depth.format);
    checkViewProjection(s.camera);

    // Medium.
    const Medium& m = f.medium;
    const std::string perMetre = "1/m; lightscatter.h, limits::kMaxCoefficient";
    s.medium.betaR = vecInRange(m.betaR, "medium.betaR", 0.0, limits::kMaxCoefficient, perMetre);
    s.medium.betaM = vecInRange(m.betaM, "medium.betaM", 0.0, limits::kMaxCoefficient, perMetre);
    s.medium.sigmaA = vecInRange(m.sigmaA, "medium.sigmaA", 0.0, limits::kMaxCoefficient, perMetre);
    if (!(m.g > -1.0f && m.g < 1.0f)) fail("medium.g = " + num(m.g) + ": must be in (-1, 1)");
    s.medium.g = m.g;
    if (m.phase != MiePhase::CornetteShanks && m.phase != MiePhase::Isotropic &&
        m.phase != MiePhase::Hazy)
        fail("medium.phase is not a MiePhase value");
    s.medium.phase = m.phase;
    if (!(m.maxDistance > 0.0f && m.maxDistance <= limits::kMaxLength))
        fail("medium.maxDistance = " + num(m.maxDistance) + ": must be in (0, " +
             num(limits::kMaxLength) + "] (metres; lightscatter.h, limits::kMaxLength)");
    s.medium.maxDistance = m.maxDistance;

    // Images.
    s.engineNoise = f.noise.has_value();
    s.depthAttachment =
        !withImages || (f.depth.usage & VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT) != 0;
    s.inscatterOut = f.inscatterOut.has_value();
    if (withImages) {
        checkImage(f.depth, "depth", VK_IMAGE_USAGE_SAMPLED_BIT);
        checkDepthFormat(f.depth.format, "depth");
        checkImage(f.color, "color", VK_IMAGE_USAGE_STORAGE_BIT);
        if (f.color.format != VK_FORMAT_R16G16B16A16_SFLOAT &&
            f.color.format != VK_FORMAT_R32G32B32A32_SFLOAT)
            fail("color.format " + rg::formatName(f.color.format) +
                 ": must be R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT (linear HDR)");
        if (f.color.extent.width != f.depth.extent.width ||
            f.color.extent.height != f.depth.extent.height)
            fail("color.extent " + std::to_string(f.color.extent.width) + "x" +
                 std::to_string(f.color.extent.height) + " differs from depth.extent " +
                 std::to_string(f.depth.extent.width) + "x" +
                 std::to_string(f.depth.extent.height));
        s.screen = f.depth.extent;
        oneLayer(&f.depth, "depth");
        oneLayer(&f.color, "color");
        oneLayer(f.noise ? &*f.noise : nullptr, "noise");
        oneLayer(f.inscatterOut ? &*f.inscatterOut : nullptr, "inscatterOut");
        if (f.noise) checkImage(*f.noise, "noise", VK_IMAGE_USAGE_SAMPLED_BIT);
        if (f.inscatterOut) {
            checkImage(*f.inscatterOut, "inscatterOut", VK_IMAGE_USAGE_STORAGE_BIT, false);
            if (f.inscatterOut->format != VK_FORMAT_R32G32B32A32_SFLOAT)
                fail("inscatterOut.format " + rg::formatName(f.inscatterOut->format) +
                     ": must be R32G32B32A32_SFLOAT");
            if (f.inscatterOut->extent.width != s.screen.width ||
                f.inscatterOut->extent.height != s.screen.height)
                fail("inscatterOut.extent differs from depth.extent");
        }
        if (f.volumeOut) {
            // Its extent is the froxel grid's, checked once the frame's method is known
            // (checkVolumeOut).
            oneLayer(&*f.volumeOut, "volumeOut");
            checkImage(*f.volumeOut, "volumeOut", VK_IMAGE_USAGE_STORAGE_BIT, false, true);
            if (f.volumeOut->format != VK_FORMAT_R16G16B16A16_SFLOAT)
                fail("volumeOut.format " + rg::formatName(f.volumeOut->format) +
                     ": must be R16G16B16A16_SFLOAT");
        }
    }
    return s;
}

void setupLight(FrameSetup& s, const LightInput& light, const LightPaths& at, bool withImages) {
    if (light.settings) {
        // The light's own settings, as if the frame's profile were Custom with them.
        s.settings = *light.settings;
        checkSettings(s.settings, at.settings);
    }
    // Light.
    const Light& l = light.light;
    s.light.kind = l.type;
    s.light.position = vecInRange(l.position, at.light + ".position", -limits::kMaxLength,
                                  limits::kMaxLength, "metres; lightscatter.h, limits::kMaxLength");
    const glm::vec3 dir = vec(l.direction, at.light + ".direction");
    // A float's square overflows from 1.8e19 and underflows below 1e-19: such lengths are
    // normalised in double (ordinary ones as they always were, to the bit).
    const glm::dvec3 dirD(dir);
    const double dirScale = std::max({std::fabs(dirD.x), std::fabs(dirD.y), std::fabs(dirD.z)});
    if (!(dirScale > 0.0)) fail(at.light + ".direction is the zero vector");
    const float dirLength = glm::length(dir);
    s.light.direction = std::isfinite(dirLength) && dirLength > 1e-12f
                            ? glm::normalize(dir)
                            : glm::vec3(glm::normalize(dirD / dirScale));
    s.light.intensity = vecInRange(l.intensity, at.light + ".intensity", 0.0, limits::kMaxIntensity,
                                   "W/m^2 or W/sr; lightscatter.h, limits::kMaxIntensity");
    if (l.type == LightType::Spot) {
        const char* why =
            "degrees; below it single precision cannot resolve the cone, at 90 the cone is no "
            "longer convex; lightscatter.h, limits::kMinConeAngleDegrees";
        inRange(l.outerConeAngleDegrees, at.light + ".outerConeAngleDegrees",
                limits::kMinConeAngleDegrees, 89.0, why);
        inRange(l.innerConeAngleDegrees, at.light + ".innerConeAngleDegrees",
                limits::kMinConeAngleDegrees, 89.0, why);
        if (l.innerConeAngleDegrees > l.outerConeAngleDegrees)
            fail(at.light + ".innerConeAngleDegrees = " + num(l.innerConeAngleDegrees) +
                 ": must be at most outerConeAngleDegrees (" + num(l.outerConeAngleDegrees) + ")");
    }
    s.light.cosOuter = std::cos(l.outerConeAngleDegrees * 3.14159265f / 180.0f);
    s.light.cosInner = l.innerConeAngleDegrees == l.outerConeAngleDegrees
                           ? s.light.cosOuter
                           : std::cos(l.innerConeAngleDegrees * 3.14159265f / 180.0f);
    if (!(l.range > 0.0f) || !finite(l.range))
        fail(at.light + ".range = " + num(l.range) + ": must be > 0 and finite (1e30: no range)");
    s.light.range = l.range;
    if (l.rangeFalloff != RangeFalloff::Cut && l.rangeFalloff != RangeFalloff::Window)
        fail(at.light + ".rangeFalloff is not a RangeFalloff value");
    s.light.windowedRange = l.rangeFalloff == RangeFalloff::Window;
    inRange(l.radius, at.light + ".radius", limits::kMinRadius, limits::kMaxLength,
            "metres; it keeps rays through the light finite, lightscatter.h, limits::kMinRadius");
    s.light.radius = l.radius;
    s.light.shadowMapSize = l.shadowMapSize;
    s.light.shadowReversedZ = l.shadowReversedZ;
    if (l.type == LightType::Point && l.shadowMapSize > 0) {
        for (size_t i = 0; i < 6; ++i)
            s.light.cubeFaceViewProj[i] = checkCubeFace(
                l.cubeFaceViewProjections[i], i, s.light.position, l.shadowReversedZ, at.light);
    } else if (l.shadowMapSize > 0 || (light.lightColor && l.type != LightType::Point)) {
        // A light color without a shadow map is projected with the same matrix (the host computes
        // it for such a spot or directional light too), so it is checked the same way.
        s.light.shadowViewProj = matrix(l.shadowViewProjection, at.light + ".shadowViewProjection");
        // An all-zero (default) or otherwise singular matrix puts every point at one texel and
        // depth: the light would silently vanish or light everything.
        if (conditioning(s.light.shadowViewProj) < 1e-9)
            fail(at.light + ".shadowViewProjection is singular (all zero?): " +
                 (l.shadowMapSize > 0
                      ? "with light.shadowMapSize " + std::to_string(l.shadowMapSize) +
                            " it must be the shadow map's world -> light clip matrix"
                      : "with " + at.lightColor +
                            " it must be the world -> light clip matrix the color is projected "
                            "with"));
        checkMatrixScale(s.light.shadowViewProj, at.light + ".shadowViewProjection");
    }

    // The light's images.
    s.shadowed = l.shadowMapSize > 0;
    s.lightColor = light.lightColor.has_value();
    if (withImages) {
        if (s.shadowed != light.shadowMap.has_value())
            fail(s.shadowed ? at.shadowMap + " is missing but " + at.light + ".shadowMapSize is " +
                                  std::to_string(l.shadowMapSize)
                            : at.shadowMap + " is given but " + at.light + ".shadowMapSize is 0");
        oneLayer(light.lightColor ? &*light.lightColor : nullptr, at.lightColor);
        if (light.shadowMap) {
            const ImageInput& map = *light.shadowMap;
            const uint32_t layers = l.type == LightType::Point ? 6 : 1;
            if (map.arrayLayers != layers)
                fail(at.shadowMap + ".arrayLayers = " + std::to_string(map.arrayLayers) +
                     ": must be " +
                     (layers == 6
                          ? std::string(
                                "6 for a point light (its cube faces +X, -X, +Y, -Y, +Z, -Z)")
                          : std::string("1 for a ") +
                                (l.type == LightType::Spot ? "spot" : "directional") +
                                " light (6 only for a point light's cube map)"));
            checkImage(map, at.shadowMap, VK_IMAGE_USAGE_SAMPLED_BIT);
            checkDepthFormat(map.format, at.shadowMap);
            if (map.extent.width != l.shadowMapSize || map.extent.height != l.shadowMapSize)
                fail(at.shadowMap + ".extent " + std::to_string(map.extent.width) + "x" +
                     std::to_string(map.extent.height) + " does not match " + at.light +
                     ".shadowMapSize " + std::to_string(l.shadowMapSize));
        }
        if (light.lightColor)
            checkImage(*light.lightColor, at.lightColor, VK_IMAGE_USAGE_SAMPLED_BIT);
    }
    // Without a shadow map the color is marched at its own resolution (a piece per texel row or
    // column crossed).
    if (light.lightColor)
        s.light.lightColorSize =
            std::max(light.lightColor->extent.width, light.lightColor->extent.height);
    if (s.lightColor && l.type == LightType::Point)
        fail(at.lightColor +
             " is not supported with a point light: a light-space color texture needs a "
             "spot or directional light's single projection (light.shadowViewProjection)");

    applySettings(s, s.settings, l.shadowMapSize);
}

FrameSetup setupFrame(const FrameDescription& f, bool withImages) {
    FrameSetup s = setupFrameWide(f, withImages);
    setupLight(s, LightInput{f.light, f.shadowMap, f.lightColor, std::nullopt}, LightPaths{},
               withImages);
    return s;
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

namespace {

bool defaultLight(const Light& l) {
    const Light d;
    return l.type == d.type && l.position == d.position && l.direction == d.direction &&
           l.intensity == d.intensity && l.innerConeAngleDegrees == d.innerConeAngleDegrees &&
           l.outerConeAngleDegrees == d.outerConeAngleDegrees && l.range == d.range &&
           l.rangeFalloff == d.rangeFalloff && l.radius == d.radius &&
           l.shadowViewProjection == d.shadowViewProjection &&
           l.cubeFaceViewProjections == d.cubeFaceViewProjections &&
           l.shadowMapSize == d.shadowMapSize && l.shadowReversedZ == d.shadowReversedZ;
}

}  // namespace

std::vector<FrameSetup> setupLights(const FrameDescription& frame, bool withImages) {
    std::string both;
    if (!defaultLight(frame.light)) both = "light";
    if (frame.shadowMap) both += both.empty() ? "shadowMap" : ", shadowMap";
    if (frame.lightColor) both += both.empty() ? "lightColor" : ", lightColor";
    if (!both.empty())
        fail("lights holds " + std::to_string(frame.lights.size()) + " lights and " + both +
             " is given too: give the single light (light, shadowMap, lightColor) or the list "
             "(lights), "
             "never both");
    if (frame.lights.size() > kMaxLights)
        fail("lights holds " + std::to_string(frame.lights.size()) + " lights: at most " +
             std::to_string(kMaxLights) +
             " (kMaxLights; each light is a chain of passes and a table of its own)");
    // The frame's own part once; whatever fails there is not about a light.
    const FrameSetup frameWide = setupFrameWide(frame, withImages);
    std::vector<FrameSetup> setups;
    setups.reserve(frame.lights.size());
    for (size_t i = 0; i < frame.lights.size(); ++i) {
        const std::string at = "lights[" + std::to_string(i) + "]";
        LightPaths paths{at + ".light", at + ".shadowMap", at + ".lightColor",
                         frame.lights[i].settings ? at + ".settings" : "custom"};
        FrameSetup s = frameWide;
        s.lightPath = paths.light;
        s.settingsPath = paths.settings;
        try {
            setupLight(s, frame.lights[i], paths, withImages);
        } catch (const InvalidInput& e) {
            throw aboutLight(e, i);
        }
        setups.push_back(std::move(s));
    }
    return setups;
}

}  // namespace lightscatter::detail

namespace lightscatter::detail {

InvalidInput aboutLight(const InvalidInput& e, size_t i) {
    const std::string lead = "lightscatter: ";
    std::string m = e.what();
    if (m.rfind(lead, 0) == 0) m = m.substr(lead.size());
    return InvalidInput(lead + "lights[" + std::to_string(i) + "]: " + m);
}

std::vector<LightInput> lightInputs(const FrameDescription& frame) {
    if (!frame.lights.empty()) return frame.lights;
    return {LightInput{frame.light, frame.shadowMap, frame.lightColor, std::nullopt}};
}

ValidatedFrame validateFrame(const FrameDescription& frame, bool withImages) {
    ValidatedFrame v;
    v.list = !frame.lights.empty();
    if (v.list) {
        v.lights = setupLights(frame, withImages);
    } else {
        v.lights.push_back(setupFrame(frame, withImages));
    }
    for (FrameSetup& s : v.lights) {
        v.touchesView.push_back(ls::lightTouchesView(s.camera, s.light, s.medium));
        s.screenRect = ls::lightScreenRect(s.camera, s.light, s.medium, s.screen);
    }
    return v;
}

}  // namespace lightscatter::detail
