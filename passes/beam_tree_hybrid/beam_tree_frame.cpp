#include "beam_tree_frame.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "beam_tree/light_volume_mesh.h"

namespace ls {
namespace {

constexpr float kNearSpacings = 4.0f;
constexpr uint32_t kNearSplit = 4;
// The slabs drawn whole beside a shadowed spot's apex: those within this many of their own
// thickness of its view depth. Measured at 320x180 against the float64 reference (mean relative
// error, none / 2 / every near slab): dense_medium 0.055 / 0.018 / 0.016, light_center 0.024 /
// 0.014 / 0.012, spot_near_edge 0.033 / 0.016 / 0.012; at 1920x1080 every near slab took
// dense_medium 22% longer than 2 (560 against 459 ms), and 2 about as long as none.
constexpr float kApexSlabs = 2.0f;

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
    // The planes within kNearSpacings spacings of the light's view depth: beyond, a slab is short
    // beside its distance from the light (under a quarter of it for rays up to 60 degrees off the
    // view axis), and the midpoint rule's error, which goes as its square, is small. Near it each
    // plane is split into kNearSplit thinner ones: there the shadows of what stands close to the
    // light (a cage's bars) change fastest along a ray, and the visibility is sampled per slab.
    const float spacing = placement.push.boxMin.w;
    const float lightDepth = -(camera.view * glm::vec4(light.position, 1.0f)).z;
    const float nearFrom = (lightDepth - placement.push.boxMin.z) / spacing - 0.5f;
    auto planeAt = [&](float index) {
        return static_cast<uint32_t>(std::clamp(index, 0.0f, static_cast<float>(placement.planes)));
    };
    // beam-tree-analytic's uncertain planes keep seed 002's even midpoints (its lit space is
    // already in closed form).
    const bool splitNear = light.kind != LightType::Directional && out.litAsPlanes;
    const uint32_t nearFirst = splitNear ? planeAt(std::ceil(nearFrom - kNearSpacings)) : 0;
    const uint32_t nearEnd =
        splitNear ? std::max(nearFirst, planeAt(std::floor(nearFrom + kNearSpacings) + 1.0f)) : 0;
    out.nearSpacing = spacing / static_cast<float>(kNearSplit);
    const glm::vec2 lo(placement.push.boxMin), hi(placement.push.boxMax);
    auto addPlane = [&](float z) {
        out.litStarts.push_back(static_cast<uint32_t>(out.points.size()));
        out.uncertainStarts.push_back(static_cast<uint32_t>(uncertain.size()));
        beam::Polygon quad;
        for (const glm::vec2& c : {lo, glm::vec2(hi.x, lo.y), hi, glm::vec2(lo.x, hi.y)})
            quad.emplace_back(glm::vec3(toWorld * glm::vec4(c, -z, 1.0f)));
        beam::appendPartitioned(volume.tree, quad, uncertain,
                                out.litAsPlanes ? &out.points : nullptr);
    };
    // A shadowed spot's slabs beside its apex are drawn whole over the polygon through which rays
    // cross the cone within them (spotSlabFootprint), all of it uncertain: there the cone is
    // narrower than a slab is long, and a plane cut to the cone at its own depth misses the rays
    // that cross it between two planes, where the light is brightest. planes.frag cuts each ray to
    // the cone and looks up the shadow map at its slab's middle. Without a shadow map the tree's
    // cut is the only shadow, and the plane keeps it.
    const bool wholeSlabs = light.kind == LightType::Spot && light.shadowMapSize > 0;
    const float split = static_cast<float>(kNearSplit);
    auto addSlab = [&](float index, float j) {
        const float z = placement.push.boxMin.z + (index + (j + 0.5f) / split) * spacing;
        const float front = placement.push.boxMin.z + (index + j / split) * spacing;
        const float back = placement.push.boxMin.z + (index + (j + 1.0f) / split) * spacing;
        if (!wholeSlabs ||
            std::max(front - lightDepth, lightDepth - back) > kApexSlabs * out.nearSpacing)
            return addPlane(z);
        out.litStarts.push_back(static_cast<uint32_t>(out.points.size()));
        out.uncertainStarts.push_back(static_cast<uint32_t>(uncertain.size()));
        // The box's first slab also stands for the ray's head, from the camera (planes.frag).
        const std::vector<glm::vec2> footprint =
            spotSlabFootprint(camera, light, medium, index + j == 0.0f ? 0.0f : front, back, z);
        for (size_t k = 1; k + 1 < footprint.size(); ++k)
            for (size_t c : {size_t{0}, k, k + 1})
                uncertain.emplace_back(glm::vec3(toWorld * glm::vec4(footprint[c], -z, 1.0f)),
                                       1.0f);
    };
    for (uint32_t i = 0; i < placement.planes; ++i) {
        const float index = static_cast<float>(i);
        if (i < nearFirst || i >= nearEnd) {
            addPlane(placement.push.boxMin.z + (index + 0.5f) * spacing);
            continue;
        }
        if (i == nearFirst) out.nearFirst = static_cast<uint32_t>(out.litStarts.size());
        for (uint32_t j = 0; j < kNearSplit; ++j) addSlab(index, static_cast<float>(j));
        if (i + 1 == nearEnd) out.nearEnd = static_cast<uint32_t>(out.litStarts.size());
    }
    out.litStarts.push_back(static_cast<uint32_t>(out.points.size()));
    out.uncertainStarts.push_back(static_cast<uint32_t>(uncertain.size()));
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
