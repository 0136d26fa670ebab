#include "bounding_boxes.h"

#include <cmath>
#include <numeric>
#include <unordered_map>

namespace host {
namespace {

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// The primitive's vertices grouped into connected parts: triangles that share a vertex position (to
// a millimetre, within a kilometre of the origin; farther positions may alias, which only joins
// parts) belong together, since glTF repeats a position for every normal it has (a flat-shaded cube
// is 24 vertices). Without indices the primitive is one part.
std::vector<std::vector<uint32_t>> connectedParts(const MeshData& mesh, const Primitive& p) {
    std::vector<uint32_t> all(p.vertexCount);
    std::iota(all.begin(), all.end(), p.firstVertex);
    if (p.indexCount < 3) return {all};
    std::unordered_map<uint64_t, uint32_t> welded;
    std::vector<uint32_t> weldOf(p.vertexCount);
    for (uint32_t i = 0; i < p.vertexCount; ++i) {
        const glm::vec3 q = glm::round(mesh.vertices[p.firstVertex + i].position * 1e3f);
        const auto key = [](float x) {
            return static_cast<uint64_t>(static_cast<int64_t>(x)) & 0x1FFFFF;
        };
        const uint64_t k = key(q.x) | key(q.y) << 21 | key(q.z) << 42;
        weldOf[i] = welded.try_emplace(k, static_cast<uint32_t>(welded.size())).first->second;
    }
    std::vector<uint32_t> parent(welded.size());
    std::iota(parent.begin(), parent.end(), 0u);
    std::vector<bool> used(p.vertexCount, false);
    for (uint32_t t = p.firstIndex; t + 2 < p.firstIndex + p.indexCount; t += 3) {
        const uint32_t a = mesh.indices[t] - p.firstVertex, b = mesh.indices[t + 1] - p.firstVertex,
                       c = mesh.indices[t + 2] - p.firstVertex;
        if (a >= p.vertexCount || b >= p.vertexCount || c >= p.vertexCount) return {all};
        used[a] = used[b] = used[c] = true;
        parent[findRoot(parent, weldOf[a])] = findRoot(parent, weldOf[b]);
        parent[findRoot(parent, weldOf[b])] = findRoot(parent, weldOf[c]);
    }
    std::unordered_map<uint32_t, size_t> partOf;
    std::vector<std::vector<uint32_t>> parts;
    for (uint32_t i = 0; i < p.vertexCount; ++i) {
        if (!used[i]) continue;
        const auto [it, added] = partOf.try_emplace(findRoot(parent, weldOf[i]), parts.size());
        if (added) parts.emplace_back();
        parts[it->second].push_back(p.firstVertex + i);
    }
    return parts;
}

BoundingBoxes boxAround(const MeshData& mesh, const std::vector<uint32_t>& vertices,
                        const glm::mat3& axes, float minHalfExtent) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (uint32_t v : vertices) {
        const glm::vec3 local = glm::transpose(axes) * mesh.vertices[v].position;
        lo = glm::min(lo, local);
        hi = glm::max(hi, local);
    }
    BoundingBoxes b;
    b.outer.axes = axes;
    b.outer.center = axes * (0.5f * (lo + hi));
    b.outer.halfExtents = glm::max(0.5f * (hi - lo), glm::vec3(minHalfExtent));
    // A solid box: every vertex at one of the box's corners (to a millimetre).
    const glm::vec3 half = 0.5f * (hi - lo);
    bool box = glm::all(glm::greaterThan(half, glm::vec3(2.0f * minHalfExtent)));
    for (size_t i = 0; box && i < vertices.size(); ++i) {
        const glm::vec3 local = glm::transpose(axes) * mesh.vertices[vertices[i]].position;
        const glm::vec3 d = glm::abs(local - 0.5f * (lo + hi)) - half;
        box = glm::all(glm::lessThan(glm::abs(d), glm::vec3(1e-3f)));
    }
    if (box) {
        OrientedBox inner = b.outer;
        inner.halfExtents = half - glm::vec3(minHalfExtent);
        b.inner = inner;
    }
    return b;
}

}  // namespace

std::vector<BoundingBoxes> boundingBoxes(const MeshData& mesh, float minHalfExtent) {
    std::vector<BoundingBoxes> out;
    for (const Primitive& p : mesh.primitives)
        for (const std::vector<uint32_t>& part : connectedParts(mesh, p))
            if (!part.empty()) out.push_back(boxAround(mesh, part, p.axes, minHalfExtent));
    return out;
}

}  // namespace host
