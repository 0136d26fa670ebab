#include "scene_to_plugin.h"

#include <cstring>

namespace host {
namespace {

lightscatter::Vec3 v3(const glm::vec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

lightscatter::Mat4 toPluginMatrix(const glm::mat4& m) {
    lightscatter::Mat4 out;
    std::memcpy(out.data(), &m[0][0], sizeof(float) * 16);
    return out;
}

lightscatter::Camera toPluginCamera(const CameraDesc& c, const glm::mat4& view, const glm::mat4& projection) {
    lightscatter::Camera out;
    out.view = toPluginMatrix(view);
    out.projection = toPluginMatrix(projection);
    out.nearPlane = c.nearPlane;
    out.farPlane = c.farPlane;
    out.reversedZ = c.reversedZ;
    out.infiniteFar = c.infiniteFar;
    return out;
}

lightscatter::Light toPluginLight(const LightDesc& l, const glm::mat4& shadowViewProj, bool shadowed) {
    lightscatter::Light out;
    out.type = l.type == LightKind::Directional ? lightscatter::LightType::Directional
               : l.type == LightKind::Spot      ? lightscatter::LightType::Spot
                                                : lightscatter::LightType::Point;
    out.position = v3(l.position);
    out.direction = v3(l.direction);
    out.intensity = v3(l.intensity);
    out.halfAngleDegrees = l.halfAngleDegrees;
    out.range = l.range;
    out.radius = l.radius;
    if (shadowed) {
        out.shadowViewProjection = toPluginMatrix(shadowViewProj);
        out.shadowMapSize = l.shadowMapSize;
    }
    return out;
}

lightscatter::Medium toPluginMedium(const MediumDesc& m) {
    lightscatter::Medium out;
    out.betaR = v3(m.betaR);
    out.betaM = v3(m.betaM);
    out.g = m.g;
    out.sigmaA = v3(m.sigmaA);
    out.phase = m.phase == PhaseKind::Isotropic ? lightscatter::MiePhase::Isotropic
                                                : lightscatter::MiePhase::CornetteShanks;
    out.maxDistance = m.maxDistance;
    return out;
}

}  // namespace host
