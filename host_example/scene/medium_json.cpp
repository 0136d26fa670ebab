#include "scene/medium_json.h"

namespace host {
namespace {

nlohmann::json vec(const lightscatter::Vec3& v) {
    return {v[0], v[1], v[2]};
}
nlohmann::json vec(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

}  // namespace

nlohmann::json mediumJson(const MediumDesc& m) {
    nlohmann::json out = {
        {"betaR", vec(m.betaR)},   {"betaM", vec(m.betaM)},        {"g", m.g},
        {"sigmaA", vec(m.sigmaA)}, {"maxDistance", m.maxDistance}, {"density", m.density}};
    out["heightFog"] = m.heightFog ? nlohmann::json{{"baseHeight", m.heightFog->baseHeight},
                                                    {"falloff", m.heightFog->falloff}}
                                   : nlohmann::json(nullptr);
    out["fogVolumes"] = nlohmann::json::array();
    for (const lightscatter::FogVolume& v : m.fogVolumes)
        out["fogVolumes"].push_back({{"center", vec(v.center)},
                                     {"halfExtents", vec(v.halfExtents)},
                                     {"axes", {vec(v.axes[0]), vec(v.axes[1]), vec(v.axes[2])}},
                                     {"density", v.density},
                                     {"fade", v.fade}});
    return out;
}

}  // namespace host
