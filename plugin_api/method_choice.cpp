#include "method_choice.h"

#include <algorithm>
#include <cstdio>

namespace lightscatter::detail {
namespace {

[[noreturn]] void refuse(const std::string& what) { throw InvalidInput("lightscatter: " + what); }

float maxOf(const glm::vec3& v) { return std::max({v.x, v.y, v.z}); }

std::string number(float x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2g", static_cast<double>(x));
    return buf;
}

std::string percent(float x) { return number(100.0f * x) + "%"; }

bool isotropicMedium(const FrameSetup& s) { return maxOf(s.medium.betaR) == 0.0f && s.medium.isotropicMie; }

float analyticOpticalDepth(const FrameSetup& s) {
    const glm::vec3 camera = glm::vec3(glm::inverse(s.camera.view)[3]);
    return maxOf(s.medium.betaT()) * glm::length(s.light.position - camera);
}

// What seed 001's closed form gets wrong for this frame, in one line (empty when nothing).
std::string analyticNotice(const FrameSetup& s) {
    std::string notice;
    if (!isotropicMedium(s))
        notice = "analytic assumes isotropic scattering, but the medium has " +
                 std::string(maxOf(s.medium.betaR) > 0.0f ? "Rayleigh scattering" : "a Mie lobe") +
                 " (its phase function is replaced by 1/(4 pi))";
    const float tau = analyticOpticalDepth(s);
    const float error = 1.33f * tau;
    if (error > 0.01f)
        notice += std::string(notice.empty() ? "analytic ignores extinction" : "; it also ignores extinction") +
                  ": optical depth " + number(tau) + " to the light, about " + percent(error) +
                  " too bright";
    return notice;
}

// Seed 002's noise is a density the model does not have; only the slice planes sample it.
void refuseNoise(const FrameSetup& s, Method m) {
    if (s.noise)
        refuse("custom.noiseAmplitude > 0 (seed 002's scrolling noise) is honoured by slices only; "
               "method " + std::string(methodName(m)) +
               " integrates the model's homogeneous medium (use slices or auto, or amplitude 0)");
}

// Seed 004's simplified light model is a different integrand; only the closed forms take it.
void refuseSimplified(const FrameSetup& s, Method m) {
    if (s.simplified)
        refuse(
            "custom.lightModel = simplified (seed 004's light model) is honoured by "
            "beam-tree-analytic and analytic only; method " +
            std::string(methodName(m)) +
            " integrates docs/model.md's full model (use beam-tree-analytic, analytic or "
            "auto, or lightModel full)");
}

bool cubeShadow(const FrameSetup& s) { return s.shadowed && s.light.kind == ls::LightKind::Point; }

// A point light's cube shadow map: epipolar (face by face) and brute force sample its six faces.
void refuseCube(const FrameSetup& s, Method m) {
    if (cubeShadow(s))
        refuse("method " + std::string(methodName(m)) +
               " cannot sample a point light's cube shadow map (light.shadowMapSize > 0 with a point "
               "light): use epipolar, brute-force or auto");
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

std::string noOccludersNotice(Method m) {
    return std::string(methodName(m)) +
           " has no occluders (FrameDescription::occluders): it treats the whole light volume as lit, so " +
           (m == Method::BeamTreeAnalytic ? "nothing casts a shadow" : "it never looks the shadow map up");
}

}  // namespace

MethodChoice chooseMethod(Method requested, const FrameSetup& s, bool lightReachesView) {
    const bool pointLike = s.light.kind != ls::LightKind::Directional;
    const bool skipShadows = !s.settings.shadowSampling && s.shadowed;
    MethodChoice c;
    c.method = requested;
    if (requested != Method::BruteForce && requested != Method::Epipolar && requested != Method::Auto)
        refuseCube(s, requested);
    switch (requested) {
        case Method::Analytic:
            if (!pointLike)
                refuse("method analytic (seed 001) is a closed form for point and spot lights; this "
                       "frame's light is directional (use auto, epipolar or cone-march)");
            if (s.shadowed)
                refuse("method analytic (seed 001) cannot cast shadows; this frame has a shadow map "
                       "(use auto, epipolar, brute-force or cone-march)");
            refuseNoise(s, requested);
            // The simplified model is seed 001's form by definition: nothing to warn about.
            if (!s.simplified) c.notice = analyticNotice(s);
            return c;
        case Method::Epipolar:
        case Method::BruteForce:
            if (skipShadows)
                refuse("custom.shadowSampling = false (seed 003's low-end mode) is honoured by "
                       "cone-march only; method " + std::string(methodName(requested)) +
                       " samples the shadow map (use cone-march or auto)");
            refuseNoise(s, requested);
            refuseSimplified(s, requested);
            return c;
        case Method::ConeMarch:
            refuseNoise(s, requested);
            refuseSimplified(s, requested);
            return c;
        case Method::BeamTreeAnalytic:
        case Method::BeamTreeSampling: {
            const std::string name = methodName(requested);
            if (!pointLike)
                refuse("method " + name + " (seed 004) builds its beam tree from a point or spot light; "
                       "this frame's light is directional (use auto, epipolar, slices or cone-march)");
            refuseNoise(s, requested);
            if (!s.depthAttachment)
                refuse("method " + name + " (seed 004) depth-tests its sampling planes against the engine's "
                       "depth: depth.usage needs DEPTH_STENCIL_ATTACHMENT beside SAMPLED");
            if (s.occluders == 0) c.notice = noOccludersNotice(requested);
            return c;
        }
        case Method::Slices:
            if (!s.depthAttachment)
                refuse("method slices (seed 002) depth-tests its planes against the engine's depth: "
                       "depth.usage needs DEPTH_STENCIL_ATTACHMENT beside SAMPLED");
            refuseSimplified(s, requested);
            return c;
        case Method::Auto:
            break;
    }
    if (!lightReachesView) {
        c.method = Method::Epipolar;
        c.reason = "the light reaches no view ray (or nothing scatters): extinction only";
    } else if (cubeShadow(s)) {
        if (s.simplified || s.noise || skipShadows)
            refuse(std::string("a point light's cube shadow map is sampled by epipolar and brute-force only, "
                               "which do not honour ") +
                   (s.simplified ? "custom.lightModel = simplified"
                    : s.noise    ? "custom.noiseAmplitude > 0"
                                 : "custom.shadowSampling = false") +
                   " (remove the shadow map or that setting)");
        epipolarOrBruteForce(s, c, "shadowed point light (a cube shadow map, marched face by face)");
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
            if (s.occluders == 0) c.notice = noOccludersNotice(Method::BeamTreeAnalytic);
        } else {
            refuse(
                "custom.lightModel = simplified with a shadow map needs method "
                "beam-tree-analytic, which depth-tests its planes against the engine's depth: "
                "depth.usage needs DEPTH_STENCIL_ATTACHMENT beside SAMPLED");
        }
    } else if (s.noise && s.depthAttachment) {
        c.method = Method::Slices;
        c.reason = "scrolling noise (custom.noiseAmplitude > 0): seed 002's slice planes, the only "
                   "method that samples it";
    } else if (s.noise) {
        refuse("custom.noiseAmplitude > 0 needs method slices, which depth-tests against the "
               "engine's depth: depth.usage needs DEPTH_STENCIL_ATTACHMENT beside SAMPLED");
    } else if (skipShadows) {
        c.method = Method::ConeMarch;
        c.reason = "shadow sampling is off: seed 003's low-end mode, which only cone-march has";
    } else if (!s.shadowed && pointLike) {
        const float tau = analyticOpticalDepth(s);
        if (isotropicMedium(s) && tau < kAnalyticMaxOpticalDepth) {
            c.method = Method::Analytic;
            c.reason = "unshadowed point light in an isotropic, thin medium (optical depth " +
                       number(tau) + " to the light): seed 001's closed form, within 1%";
        } else {
            c.method = Method::Epipolar;  // an unshadowed frame is the table in closed form
            c.reason = std::string("unshadowed point light: the point-light table per pixel (") +
                       (isotropicMedium(s) ? "the optical depth to the light, " + number(tau) +
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

}  // namespace lightscatter::detail
