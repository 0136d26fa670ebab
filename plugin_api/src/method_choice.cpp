#include "method_choice.h"

#include <algorithm>
#include <cstdio>

#include "method_units.h"
#include "occluder_input.h"
#include "shared/refusals.h"

namespace lightscatter::detail {
namespace {

[[noreturn]] void refuse(const std::string& what) {
    throw InvalidInput("lightscatter: " + what);
}

MethodChoice pick(Method method, std::string reason) {
    MethodChoice c;
    c.method = method;
    c.reason = std::move(reason);
    return c;
}

// Auto's default: epipolar sampling (an unshadowed light is its closed form per pixel).
MethodChoice sampled(std::string reason) {
    return pick(Method::Epipolar, std::move(reason));
}

// Seed 001's closed form, where it is exact enough.
MethodChoice closedForm(std::string reason) {
    return pick(Method::Analytic, std::move(reason));
}

// Epipolar sampling for a shadowed light, unless the screen is too small for it to pay, or the
// light covers so little of it that marching its pixels costs less than epipolar's samples and
// full-screen passes.
MethodChoice epipolarOrBruteForce(const FrameSetup& s, const std::string& light) {
    const uint64_t pixels = uint64_t{s.screen.width} * s.screen.height;
    const uint64_t samples = uint64_t{s.settings.slices} * s.settings.samplesPerSlice;
    const uint64_t covered = uint64_t{s.screenRect.extent.width} * s.screenRect.extent.height;
    const uint64_t texels = std::max(1u, s.light.shadowMapSize);
    if (covered != 0 && covered * texels <= pixels * kMarchTexelsPerPixel) {
        char share[96];
        std::snprintf(
            share, sizeof share, "%.1f%% of the screen (at most %.1f%% with a %u-texel map)",
            100.0 * static_cast<double>(covered) / static_cast<double>(pixels),
            100.0 * kMarchTexelsPerPixel / static_cast<double>(texels), s.light.shadowMapSize);
        return pick(Method::BruteForce,
                    light + " within " + share + ": brute force marches only its screen rectangle");
    }
    if (pixels * kEpipolarSamplesPerPixel >= samples) return sampled(light + ": epipolar sampling");
    return pick(Method::BruteForce,
                light + " on a screen of " + std::to_string(pixels) + " pixels, fewer than " +
                    std::to_string(samples / kEpipolarSamplesPerPixel) + " (epipolar samples / " +
                    std::to_string(kEpipolarSamplesPerPixel) + "): per-pixel marching is cheaper");
}

// Auto: the cheapest method that meets the frame's needs, and why.
MethodChoice autoChoice(const FrameSetup& s, bool lightReachesView) {
    const bool pointLike = ls::pointLike(s);
    const bool skipShadows = ls::skipsShadows(s);
    const std::string& set = s.settingsPath;  // "custom", or the light's own settings
    if (!lightReachesView)
        return sampled("the light reaches no view ray (or nothing scatters): extinction only");
    // A point light's cube map, with none of the settings below (which pick the method that
    // honours them; each samples the cube map too).
    if (ls::cubeShadowed(s) && !s.simplified && !s.noise && !skipShadows)
        return epipolarOrBruteForce(
            s, "shadowed point light (a cube shadow map, marched face by face)");
    if (s.simplified) {
        // Seed 004's light model: only its closed forms integrate it.
        if (!pointLike)
            refuse(set +
                   ".lightModel = simplified (seed 004's light model) needs a point or spot light; "
                   "this frame's light is directional (use lightModel full)");
        if (s.noise)
            refuse(set + ".lightModel = simplified and " + set +
                   ".noiseAmplitude > 0: no method honours both (the noise is planes', the "
                   "simplified model beam-tree-analytic's and analytic's)");
        if (skipShadows)
            refuse(set + ".lightModel = simplified and " + set +
                   ".shadowSampling = false: no method honours both (use shadowSampling true, or "
                   "no shadow map, which analytic then integrates)");
        if (s.lightColor)
            refuse(set + ".lightModel = simplified and " + s.lightPath +
                   "Color: no method honours both (the simplified model's closed forms cannot "
                   "vary the light's color along a ray)");
        if (!s.shadowed)
            return closedForm(
                "unshadowed point light, seed 004's simplified light model: its closed form (2.17) "
                "per pixel");
        if (!s.depthAttachment)
            refuse(set +
                   ".lightModel = simplified with a shadow map needs method beam-tree-analytic, "
                   "which depth-tests its planes against the engine's depth: depth.usage needs "
                   "DEPTH_STENCIL_ATTACHMENT beside SAMPLED");
        return pick(
            Method::BeamTreeAnalytic,
            "shadowed light, seed 004's simplified light model: beam-tree-analytic, its closed "
            "form in the lit space and sampling planes elsewhere");
    }
    if (s.noise) {
        if (!s.depthAttachment)
            refuse(set +
                   ".noiseAmplitude > 0 needs method planes, which depth-tests against the "
                   "engine's depth: depth.usage needs DEPTH_STENCIL_ATTACHMENT beside SAMPLED");
        return pick(Method::Planes, "scrolling noise (" + set +
                                        ".noiseAmplitude > 0): seed 002's planes, the only "
                                        "method that samples it");
    }
    if (skipShadows)
        return pick(Method::ConeMarch,
                    "shadow sampling is off: seed 003's low-end mode, which only cone-march has");
    // A light color without a shadow map varies the light along each ray: no closed form carries
    // it, so the light is marched per pixel through the color (epipolar's unshadowed form).
    if (!s.shadowed && s.lightColor)
        return sampled(
            "unshadowed light with a light color: marched per pixel through the color (the closed "
            "forms cannot vary it along a ray)");
    if (!s.shadowed && pointLike) {
        const float tau = ls::opticalDepthToLight(s);
        if (ls::isotropicMedium(s) && tau < kAnalyticMaxOpticalDepth)
            return closedForm(
                "unshadowed point light in an isotropic, thin medium (optical depth " +
                ls::twoDigits(tau) + " to the light): seed 001's closed form, within 1%");
        return sampled(std::string("unshadowed point light: the point-light table per pixel (") +
                       (ls::isotropicMedium(s)
                            ? "the optical depth to the light, " + ls::twoDigits(tau) +
                                  ", puts seed 001's closed form over 1%"
                            : "seed 001's closed form assumes isotropic scattering") +
                       ")");
    }
    if (!s.shadowed) return sampled("unshadowed directional light: closed form per pixel");
    return epipolarOrBruteForce(s, "shadowed light");
}

}  // namespace

const ls::MethodUnit& MethodChoice::unit() const {
    return *methodUnit(method);
}

MethodChoice chooseMethod(Method requested, const FrameSetup& s, bool lightReachesView) {
    MethodChoice c;
    if (requested == Method::Auto) {
        c = autoChoice(s, lightReachesView);
        // Auto picks a method that honours the frame; its notice still says what it assumes.
        if (c.unit().caps().readsOccluders) c.notice = c.unit().notice(s);
        return c;
    }
    const ls::MethodUnit* unit = methodUnit(requested);
    if (!unit) refuse("method is not a Method value");
    if (const std::string r = unit->refusal(s); !r.empty()) refuse(r);
    c.method = requested;
    c.notice = unit->notice(s);
    return c;
}

std::vector<MethodChoice> chooseLightMethods(Method frameMethod, ValidatedFrame& v,
                                             const FrameDescription& frame) {
    const size_t n = v.lights.size();
    const std::vector<LightInput> inputs = lightInputs(frame);
    std::vector<MethodChoice> choices(n);
    bool occluders = false;
    for (size_t i = 0; i < n; ++i) {
        // A light's own method overrides the frame's; its Auto follows the frame's.
        const Method requested =
            v.list && inputs[i].method != Method::Auto ? inputs[i].method : frameMethod;
        try {
            choices[i] = chooseMethod(requested, v.lights[i], v.touchesView[i]);
        } catch (const InvalidInput& e) {
            if (!v.list) throw;
            throw aboutLight(e, i);
        }
    }
    // A frame-wide method (froxels) takes every light into one chain: once one light resolves to
    // it, the lights that follow the frame's method go with it, and one that names another
    // method is refused.
    for (size_t i = 0; i < n; ++i) {
        if (!choices[i].unit().caps().frameWide) continue;
        const Method wide = choices[i].method;
        for (size_t j = 0; j < n; ++j) {
            if (choices[j].method == wide) continue;
            const bool own = v.list && inputs[j].method != Method::Auto;
            if (own)
                refuse("lights[" + std::to_string(j) +
                       "].method = " + methodName(inputs[j].method) + ": " + methodName(wide) +
                       " (lights[" + std::to_string(i) +
                       "]'s) takes every light of the frame into one grid and mixes with no "
                       "other method; leave lights[" +
                       std::to_string(j) + "].method auto, or choose no " + methodName(wide));
            try {
                choices[j] = chooseMethod(wide, v.lights[j], v.touchesView[j]);
                choices[j].reason = methodName(wide) +
                                    std::string(" takes every light of the frame (lights[") +
                                    std::to_string(i) + "] resolved to it)";
            } catch (const InvalidInput& e) {
                if (!v.list) throw;
                throw aboutLight(e, j);
            }
        }
        break;
    }
    for (size_t i = 0; i < n; ++i)
        occluders = occluders || (v.touchesView[i] && choices[i].unit().caps().readsOccluders);
    // Checked, and converted, only when a light's method reads them: the others ignore them, as
    // the header says, and a scene of 100,000 parts must not stop them.
    if (occluders) {
        const std::vector<ls::beam::Occluder> converted = beamOccluders(frame.occluders);
        for (size_t i = 0; i < n; ++i)
            if (v.touchesView[i] && choices[i].unit().caps().readsOccluders)
                v.lights[i].beamOccluders = converted;
    }
    return choices;
}

}  // namespace lightscatter::detail
