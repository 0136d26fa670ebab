#include "occluders.h"

#include "front_to_back.h"
#include "shared/spot_basis.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ls::beam {
namespace {

double distanceToBox(const OrientedBox& b, const glm::dvec3& p) {
    const glm::dvec3 local = glm::transpose(b.axes) * (p - b.center);
    const glm::dvec3 outside = glm::max(glm::abs(local) - b.halfExtents, glm::dvec3(0.0));
    return glm::length(outside);
}

}  // namespace

std::vector<Polygon> lightFacingFaces(const OrientedBox& box, const glm::dvec3& light) {
    std::vector<Polygon> faces;
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
            const glm::dvec3 n = box.axes[axis] * sign;
            const glm::dvec3 centre = box.center + n * box.halfExtents[axis];
            if (glm::dot(n, light - centre) <= 0.0) continue;  // faces away from the light
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            const glm::dvec3 u = box.axes[a] * box.halfExtents[a],
                             v = box.axes[b] * box.halfExtents[b];
            Polygon f{centre - u - v, centre + u - v, centre + u + v, centre - u + v};
            if (glm::dot(glm::cross(f[1] - f[0], f[2] - f[0]), n) < 0.0)
                std::reverse(f.begin(), f.end());
            faces.push_back(std::move(f));
        }
    return faces;
}

LightFrustum spotFrustum(const glm::dvec3& position, const glm::dvec3& axis, double halfAngle,
                         double range) {
    LightFrustum f;
    f.position = position;
    const glm::dvec3 a = glm::normalize(axis);
    const auto [r, u] = acrossAxis(a);
    const double t = std::tan(halfAngle);
    const glm::dvec3 corners[4] = {a + t * (-r - u), a + t * (r - u), a + t * (r + u),
                                   a + t * (-r + u)};
    for (int i = 0; i < 4; ++i) {
        Plane w = Plane::through(position, position + corners[i], position + corners[(i + 1) % 4]);
        if (w.distance(position + a) < 0.0) w = w.flipped();  // the axis is inside
        f.walls.push_back(w);
        f.far.push_back(position + range * corners[i]);
    }
    return f;
}

LightVolume buildLightVolume(const LightFrustum& frustum, const std::vector<Occluder>& occluders,
                             double epsilon) {
    LightVolume v{BeamTree(frustum.position, frustum.walls, epsilon)};
    std::vector<Polygon> outer, inner;
    for (const Occluder& o : occluders) {
        if (distanceToBox(o.outer, frustum.position) == 0.0) v.tree.markAllUncertain();
        for (Polygon& face : lightFacingFaces(o.outer, frustum.position))
            outer.push_back(std::move(face));
        if (o.inner)
            for (Polygon& face : lightFacingFaces(*o.inner, frustum.position))
                inner.push_back(std::move(face));
    }
    for (const Polygon& piece : frontToBack(std::move(outer), frustum.position, epsilon)) {
        v.tree.insert(piece);
        ++v.outerPolygons;
    }
    if (!frustum.far.empty()) v.tree.addBackplate(frustum.far);
    for (const Polygon& piece : frontToBack(std::move(inner), frustum.position, epsilon)) {
        v.tree.insertStopper(piece);
        ++v.stopperPolygons;
    }
    return v;
}

}  // namespace ls::beam
