#include "occluders.h"

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

// World bounds of a box.
void bounds(const OrientedBox& b, glm::dvec3& lo, glm::dvec3& hi) {
    glm::dvec3 extent(0.0);
    for (int i = 0; i < 3; ++i) extent += glm::abs(b.axes[i]) * b.halfExtents[i];
    lo = b.center - extent;
    hi = b.center + extent;
}

double volume(const OrientedBox& b) {
    return b.halfExtents.x * b.halfExtents.y * b.halfExtents.z;
}

size_t findRoot(std::vector<size_t>& parent, size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

}  // namespace

std::vector<Occluder> mergeOverlapping(const std::vector<Occluder>& occluders) {
    const size_t n = occluders.size();
    std::vector<glm::dvec3> lo(n), hi(n);
    for (size_t i = 0; i < n; ++i) bounds(occluders[i].outer, lo[i], hi[i]);
    // Sweep along x: only boxes whose x ranges overlap are compared.
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), size_t{0});
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return lo[a].x < lo[b].x; });
    std::vector<size_t> parent(n);
    std::iota(parent.begin(), parent.end(), size_t{0});
    for (size_t a = 0; a < n; ++a)
        for (size_t b = a + 1; b < n && lo[order[b]].x <= hi[order[a]].x; ++b) {
            const size_t i = order[a], j = order[b];
            if (lo[i].y <= hi[j].y && lo[j].y <= hi[i].y && lo[i].z <= hi[j].z &&
                lo[j].z <= hi[i].z)
                parent[findRoot(parent, i)] = findRoot(parent, j);
        }
    std::vector<std::vector<size_t>> groups(n);
    for (size_t i = 0; i < n; ++i) groups[findRoot(parent, i)].push_back(i);
    std::vector<Occluder> out;
    for (const auto& g : groups) {
        if (g.empty()) continue;
        if (g.size() == 1) {
            out.push_back(occluders[g[0]]);
            continue;
        }
        glm::dvec3 glo(1e300), ghi(-1e300);
        const Occluder* biggestInner = nullptr;
        for (size_t i : g) {
            glo = glm::min(glo, lo[i]);
            ghi = glm::max(ghi, hi[i]);
            const auto& inner = occluders[i].inner;
            if (inner && (!biggestInner || volume(*inner) > volume(*biggestInner->inner)))
                biggestInner = &occluders[i];
        }
        Occluder merged;
        merged.outer.center = 0.5 * (glo + ghi);
        merged.outer.axes = glm::dmat3(1.0);
        merged.outer.halfExtents = 0.5 * (ghi - glo);
        if (biggestInner) merged.inner = biggestInner->inner;
        out.push_back(merged);
    }
    return out;
}

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
    const glm::dvec3 helper = std::abs(a.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 r = glm::normalize(glm::cross(a, helper)), u = glm::cross(r, a);
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

LightVolume buildLightVolume(const LightFrustum& frustum, const std::vector<Occluder>& given,
                             double epsilon) {
    LightVolume v{BeamTree(frustum.position, frustum.walls, epsilon)};
    const std::vector<Occluder> occluders = mergeOverlapping(given);
    std::vector<size_t> order(occluders.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::vector<double> distance(occluders.size());
    for (size_t i = 0; i < occluders.size(); ++i)
        distance[i] = distanceToBox(occluders[i].outer, frustum.position);
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return distance[a] < distance[b]; });
    for (size_t i : order)
        for (const Polygon& face : lightFacingFaces(occluders[i].outer, frustum.position)) {
            v.tree.insert(face);
            ++v.outerPolygons;
        }
    for (const Occluder& o : occluders)
        if (distanceToBox(o.outer, frustum.position) == 0.0) v.tree.markAllUncertain();
    if (!frustum.far.empty()) v.tree.addBackplate(frustum.far);
    for (size_t i : order) {
        if (!occluders[i].inner) continue;
        for (const Polygon& face : lightFacingFaces(*occluders[i].inner, frustum.position)) {
            v.tree.insertStopper(face);
            ++v.stopperPolygons;
        }
    }
    return v;
}

}  // namespace ls::beam
