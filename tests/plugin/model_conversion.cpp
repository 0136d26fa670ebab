#include "model_conversion.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace plugin_test {

ls::ref::Medium refMedium(const lightscatter::Medium& m) {
    ls::ref::Medium r;
    r.betaR = {m.betaR[0], m.betaR[1], m.betaR[2]};
    r.betaM = {m.betaM[0], m.betaM[1], m.betaM[2]};
    r.sigmaA = {m.sigmaA[0], m.sigmaA[1], m.sigmaA[2]};
    r.g = m.g;
    r.miePhase = m.phase == lightscatter::MiePhase::Isotropic ? ls::ref::Medium::Isotropic
                 : m.phase == lightscatter::MiePhase::Hazy    ? ls::ref::Medium::Hazy
                                                               : ls::ref::Medium::CornetteShanks;
    r.maxDistance = m.maxDistance;
    return r;
}

ls::ref::Light refLight(const lightscatter::Light& l) {
    ls::ref::Light r;
    r.type = l.type == lightscatter::LightType::Directional ? ls::ref::Light::Directional
             : l.type == lightscatter::LightType::Spot      ? ls::ref::Light::Spot
                                                            : ls::ref::Light::Point;
    r.position = {l.position[0], l.position[1], l.position[2]};
    r.direction = glm::normalize(glm::dvec3(l.direction[0], l.direction[1], l.direction[2]));
    r.intensity = {l.intensity[0], l.intensity[1], l.intensity[2]};
    r.halfAngle = glm::radians(static_cast<double>(l.halfAngleDegrees));
    r.range = l.range;
    r.r0 = l.radius;
    return r;
}

}  // namespace plugin_test
