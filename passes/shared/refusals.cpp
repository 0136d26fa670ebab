#include "refusals.h"

#include <algorithm>
#include <cstdio>

namespace ls {

std::string refuseCubeShadow(const LightSetup& s, const std::string& method) {
    if (!cubeShadowed(s)) return {};
    return "method " + method + " cannot sample a point light's cube shadow map (" + s.lightPath +
           ".shadowMapSize > 0 with a point light): use epipolar, brute-force or auto";
}

std::string refuseNoise(const LightSetup& s, const std::string& method) {
    if (!s.noise) return {};
    return s.settingsPath +
           ".noiseAmplitude > 0 (seed 002's scrolling noise) is honoured by planes only; method " +
           method +
           " integrates the model's homogeneous medium (use planes or auto, or amplitude 0)";
}

std::string refuseSimplified(const LightSetup& s, const std::string& method) {
    if (!s.simplified) return {};
    return s.settingsPath +
           ".lightModel = simplified (seed 004's light model) is honoured by beam-tree-analytic "
           "and "
           "analytic only; method " +
           method +
           " integrates docs/model.md's full model (use beam-tree-analytic, analytic or auto, or "
           "lightModel full)";
}

std::string refuseSkippedShadows(const LightSetup& s, const std::string& method) {
    if (!skipsShadows(s)) return {};
    return s.settingsPath +
           ".shadowSampling = false (seed 003's low-end mode) is honoured by cone-march only; "
           "method " +
           method + " samples the shadow map (use cone-march or auto)";
}

std::string refuseNoDepthAttachment(const LightSetup& s, const std::string& what) {
    if (s.depthAttachment) return {};
    return what +
           " against the engine's depth: depth.usage needs DEPTH_STENCIL_ATTACHMENT beside SAMPLED";
}

std::string refuseUnshadowedLightColor(const LightSetup& s, const std::string& method,
                                       const std::string& how) {
    if (!s.lightColor || s.shadowed) return {};
    // lightPath is "light" or "lights[i].light": the color is its sibling field.
    return "method " + method + " " + how +
           " and cannot vary its color along the ray: " + s.lightPath +
           "Color without a shadow map needs epipolar, brute-force, cone-march, " +
           "planes or auto";
}

std::string firstRefusal(std::initializer_list<std::string> refusals) {
    for (const std::string& r : refusals)
        if (!r.empty()) return r;
    return {};
}

namespace {
float maxOf(const glm::vec3& v) {
    return std::max({v.x, v.y, v.z});
}
}  // namespace

bool isotropicMedium(const LightSetup& s) {
    return maxOf(s.medium.betaR) == 0.0f && s.medium.phase == MiePhase::Isotropic;
}

float opticalDepthToLight(const LightSetup& s) {
    const glm::vec3 camera = glm::vec3(glm::inverse(s.camera.view)[3]);
    return maxOf(s.medium.betaT()) * glm::length(s.light.position - camera);
}

std::string twoDigits(float x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2g", static_cast<double>(x));
    return buf;
}

}  // namespace ls
