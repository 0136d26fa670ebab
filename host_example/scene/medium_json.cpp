#include "scene/medium_json.h"

namespace host {
namespace {

nlohmann::json jsonVec(const lightscatter::Vec3& v) {
    return {v[0], v[1], v[2]};
}
nlohmann::json jsonVec(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

}  // namespace

nlohmann::json mediumJson(const MediumDesc& m) {
    nlohmann::json out = {
        {"betaR", jsonVec(m.betaR)},   {"betaM", jsonVec(m.betaM)},    {"g", m.g},
        {"sigmaA", jsonVec(m.sigmaA)}, {"maxDistance", m.maxDistance}, {"density", m.density}};
    out["heightFog"] = m.heightFog ? nlohmann::json{{"baseHeight", m.heightFog->baseHeight},
                                                    {"falloff", m.heightFog->falloff}}
                                   : nlohmann::json(nullptr);
    out["fogVolumes"] = nlohmann::json::array();
    for (const lightscatter::FogVolume& v : m.fogVolumes)
        out["fogVolumes"].push_back(
            {{"center", jsonVec(v.center)},
             {"halfExtents", jsonVec(v.halfExtents)},
             {"axes", {jsonVec(v.axes[0]), jsonVec(v.axes[1]), jsonVec(v.axes[2])}},
             {"density", v.density},
             {"fade", v.fade}});
    return out;
}

}  // namespace host
