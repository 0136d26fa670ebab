#include "method_choice.h"

#include "method_units.h"
#include "shared/refusals.h"

namespace lightscatter::detail {
namespace {

[[noreturn]] void refuse(const std::string& what) {
    throw InvalidInput("lightscatter: " + what);
}

// Epipolar sampling for a shadowed light, unless the screen is too small for it to pay.
void epipolarOrBruteForce(const FrameSetup& s, MethodChoice& c, const std::string& light) {
    const uint64_t pixels = uint64_t{s.screen.width} * s.screen.height;
    const uint64_t samples = uint64_t{s.settings.slices} * s.settings.samplesPerSlice;
    if (pixels * kEpipolarSamplesPerPixel < samples) {
        c.method = Method::BruteForce;
        c.reason = light + " on a screen of " + std::to_string(pixels) + " pixels, fewer than " +
                   std::to_string(samples / kEpipolarSamplesPerPixel) + " (epipolar samples / " +
                   std::to_string(kEpipolarSamplesPerPixel) + "): per-pixel marching is cheaper";
    } else {
        c.method = Method::Epipolar;
        c.reason = light + ": epipolar sampling";
    }
}

// Auto: the cheapest method that meets the frame's needs, and why.
MethodChoice autoChoice(const FrameSetup& s, bool lightReachesView) {
    const bool pointLike = ls::pointLike(s);
    const bool skipShadows = ls::skipsShadows(s);
    MethodChoice c;
    if (!lightReachesView) {
        c.method = Method::Epipolar;
        c.reason = "the light reaches no view ray (or nothing scatters): extinction only";
    } else if (ls::cubeShadowed(s)) {
        if (s.simplified || s.noise || skipShadows)
            refuse(
                std::string(
                    "a point light's cube shadow map is sampled by epipolar and brute-force only, "
                    "which do not honour ") +
                (s.simplified ? "custom.lightModel = simplified"
                 : s.noise    ? "custom.noiseAmplitude > 0"
                              : "custom.shadowSampling = false") +
                " (remove the shadow map or that setting)");
        epipolarOrBruteForce(s, c,
                             "shadowed point light (a cube shadow map, marched face by face)");
    } else if (s.simplified) {
        // Seed 004's light model: only its closed forms integrate it.
        if (!pointLike)
            refuse(
                "custom.lightModel = simplified (seed 004's light model) needs a point or "
                "spot light; this frame's light is directional (use lightModel full)");
        if (s.noise)
            refuse(
                "custom.lightModel = simplified and custom.noiseAmplitude > 0: no method "
                "honours both (the noise is slices', the simplified model "
                "beam-tree-analytic's and analytic's)");
        if (skipShadows)
            refuse(
                "custom.lightModel = simplified and custom.shadowSampling = false: no method "
                "honours both (use shadowSampling true, or no shadow map, which analytic "
                "then integrates)");
        if (!s.shadowed) {
            c.method = Method::Analytic;
            c.reason =
                "unshadowed point light, seed 004's simplified light model: its closed form "
                "(2.17) per pixel";
        } else if (s.depthAttachment) {
            c.method = Method::BeamTreeAnalytic;
            c.reason =
                "shadowed light, seed 004's simplified light model: beam-tree-analytic, its closed "
                "form in the lit space and sampling planes elsewhere";
        } else {
            refuse(
                "custom.lightModel = simplified with a shadow map needs method "
                "beam-tree-analytic, which depth-tests its planes against the engine's depth: "
                "depth.usage needs DEPTH_STENCIL_ATTACHMENT beside SAMPLED");
        }
    } else if (s.noise && s.depthAttachment) {
        c.method = Method::Slices;
        c.reason =
            "scrolling noise (custom.noiseAmplitude > 0): seed 002's slice planes, the only "
            "method that samples it";
    } else if (s.noise) {
        refuse(
            "custom.noiseAmplitude > 0 needs method slices, which depth-tests against the "
            "engine's depth: depth.usage needs DEPTH_STENCIL_ATTACHMENT beside SAMPLED");
    } else if (skipShadows) {
        c.method = Method::ConeMarch;
        c.reason = "shadow sampling is off: seed 003's low-end mode, which only cone-march has";
    } else if (!s.shadowed && pointLike) {
        const float tau = ls::opticalDepthToLight(s);
        if (ls::isotropicMedium(s) && tau < kAnalyticMaxOpticalDepth) {
            c.method = Method::Analytic;
            c.reason = "unshadowed point light in an isotropic, thin medium (optical depth " +
                       ls::twoDigits(tau) + " to the light): seed 001's closed form, within 1%";
        } else {
            c.method = Method::Epipolar;  // an unshadowed frame is the table in closed form
            c.reason =
                std::string("unshadowed point light: the point-light table per pixel (") +
                (ls::isotropicMedium(s) ? "the optical depth to the light, " + ls::twoDigits(tau) +
                                              ", puts seed 001's closed form over 1%"
                                        : "seed 001's closed form assumes isotropic scattering") +
                ")";
        }
    } else if (!s.shadowed) {
        c.method = Method::Epipolar;
        c.reason = "unshadowed directional light: closed form per pixel";
    } else {
        epipolarOrBruteForce(s, c, "shadowed light");
    }
    return c;
}

}  // namespace

MethodChoice chooseMethod(Method requested, const FrameSetup& s, bool lightReachesView) {
    MethodChoice c;
    if (requested == Method::Auto) {
        c = autoChoice(s, lightReachesView);
        c.unit = methodUnit(c.method);
        // Auto picks a method that honours the frame; its notice still says what it assumes.
        if (c.unit->caps().readsOccluders) c.notice = c.unit->notice(s);
        return c;
    }
    c.method = requested;
    c.unit = methodUnit(requested);
    if (!c.unit) refuse("method is not a Method value");
    if (const std::string r = c.unit->refusal(s); !r.empty()) refuse(r);
    c.notice = c.unit->notice(s);
    return c;
}

MethodChoice chooseFrameMethod(Method requested, ValidatedFrame& v, const FrameDescription& frame) {
    const size_t n = v.lights.size();
    MethodChoice c;
    if (n == 1) {
        try {
            c = chooseMethod(requested, v.lights[0], v.touchesView[0]);
        } catch (const InvalidInput& e) {
            if (!v.list) throw;
            throw InvalidInput("lightscatter: lights[0]: " + std::string(e.what()).substr(14));
        }
    } else {
        c.method = requested == Method::Auto ? Method::Epipolar : requested;
        c.unit = methodUnit(c.method);
        if (!c.unit) refuse("method is not a Method value");
        if (requested == Method::Auto)
            c.reason = std::to_string(n) + " lights: epipolar sampling per shadowed light";
        else if (!c.unit->caps().severalLights)
            refuse(std::string("method ") + c.unit->name() +
                   " renders one light per frame so far; lights holds " + std::to_string(n) +
                   " (use epipolar, brute-force or auto, or one light)");
        for (size_t i = 0; i < n; ++i)
            if (const std::string r = c.unit->refusal(v.lights[i]); !r.empty())
                refuse("lights[" + std::to_string(i) + "]: " + r);
    }
    // Checked, and converted, only for the methods that read them: the others ignore them, as
    // the header says, and a scene of 100,000 parts must not stop them.
    if (c.unit->caps().readsOccluders) {
        const std::vector<ls::beam::Occluder> occluders = beamOccluders(frame.occluders);
        for (size_t i = 0; i < n; ++i)
            if (v.touchesView[i]) v.lights[i].beamOccluders = occluders;
    }
    return c;
}

}  // namespace lightscatter::detail
