#include "beam_tree_frame.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "beam_tree/light_volume_mesh.h"

namespace ls {
namespace {

// Six squares around a point light, `r` from it: the backplate of a light with no walls.
std::vector<beam::Polygon> cubeFaces(const glm::dvec3& c, double r) {
    std::vector<beam::Polygon> faces;
    for (int axis = 0; axis < 3; ++axis)
        for (double s : {-1.0, 1.0}) {
            glm::dvec3 n(0.0), u(0.0), v(0.0);
            n[axis] = s * r;
            u[(axis + 1) % 3] = r;
            v[(axis + 2) % 3] = r;
            faces.push_back({c + n - u - v, c + n + u - v, c + n + u + v, c + n - u + v});
        }
    return faces;
}

}  // namespace

BeamTreeFrame buildBeamTreeFrame(const CameraParams& camera, const LightParams& light,
                                 const MediumParams& medium,
                                 const std::vector<beam::Occluder>& occluders,
                                 const PlaneSettings& planes, LitSpace lit) {
    const auto start = std::chrono::steady_clock::now();
    BeamTreeFrame out;
    const glm::dvec3 L(light.position);
    const glm::vec3 cameraPos = glm::vec3(glm::inverse(camera.view)[3]);
    const double reach =
        glm::length(light.position - cameraPos) +
        static_cast<double>(camera.infiniteFar ? medium.maxDistance
                                               : std::min(camera.farPlane, medium.maxDistance)) *
            2.0;
    beam::LightFrustum frustum;
    if (light.kind == LightType::Spot) {
        const double halfAngle =
            std::acos(std::clamp(static_cast<double>(light.cosOuter), -1.0, 1.0));
        frustum = beam::spotFrustum(L, glm::dvec3(light.direction), halfAngle,
                                    std::min(static_cast<double>(light.range), reach));
    } else {
        frustum.position = L;  // no walls, and the cube below as its backplate
    }
    beam::LightVolume volume = beam::buildLightVolume(frustum, occluders);
    if (light.kind != LightType::Spot)
        for (const beam::Polygon& face : cubeFaces(L, reach)) volume.tree.addBackplate(face);
    out.litAsPlanes = lit == LitSpace::Planes;
    if (!out.litAsPlanes) beam::appendLitPyramids(volume.tree, out.points);

    // Seed 002's planes across the light's volume, cut to its uncertain (and lit) parts.
    std::vector<glm::vec4> uncertain;
    const PlanePlacement placement = placePlanes(camera, light, medium, planes, 0.0);
    out.planePush = placement.push;
    const glm::mat4 toWorld = placement.push.viewToWorld;
    for (uint32_t i = 0; i < placement.planes; ++i) {
        const float z =
            placement.push.boxMin.z + (static_cast<float>(i) + 0.5f) * placement.push.boxMin.w;
        const glm::vec2 lo(placement.push.boxMin), hi(placement.push.boxMax);
        beam::Polygon quad;
        for (const glm::vec2& c : {lo, glm::vec2(hi.x, lo.y), hi, glm::vec2(lo.x, hi.y)})
            quad.emplace_back(glm::vec3(toWorld * glm::vec4(c, -z, 1.0f)));
        beam::appendPartitioned(volume.tree, quad, uncertain,
                                out.litAsPlanes ? &out.points : nullptr);
    }
    out.litPoints = static_cast<uint32_t>(out.points.size());
    out.uncertainPoints = static_cast<uint32_t>(uncertain.size());
    out.points.insert(out.points.end(), uncertain.begin(), uncertain.end());
    out.treeNodes = volume.tree.nodeCount();
    out.visiblePolygons = volume.tree.visibleSet().size();
    out.buildMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace ls
