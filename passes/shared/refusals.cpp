#include "refusals.h"

#include <algorithm>
#include <cstdio>

namespace ls {

std::string refuseNoDepthAttachment(const LightSetup& s, const std::string& what) {
    if (s.depthAttachment) return {};
    return what +
           " against the engine's depth: depth.usage needs DEPTH_STENCIL_ATTACHMENT beside SAMPLED";
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
