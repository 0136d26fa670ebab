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

std::vector<BoundingBoxes> gridBoxes(const MeshData& mesh, size_t maxBoxes, float minHalfExtent) {
    Bounds all;
    for (const Vertex& v : mesh.vertices) all.add(v.position);
    if (all.empty() || maxBoxes == 0) return {};
    const glm::vec3 extent = glm::max(all.max - all.min, glm::vec3(minHalfExtent));
    // Doubling the axis whose cells are longest keeps the cells near cubic, within the count.
    glm::ivec3 dims(1);
    while (true) {
        const glm::vec3 cell = extent / glm::vec3(dims);
        const int axis = cell.x >= cell.y && cell.x >= cell.z ? 0 : cell.y >= cell.z ? 1 : 2;
        if (size_t(dims.x) * size_t(dims.y) * size_t(dims.z) * 2 > maxBoxes) break;
        dims[axis] *= 2;
    }
    const glm::vec3 cellSize = extent / glm::vec3(dims);
    std::vector<Bounds> cells(size_t(dims.x) * size_t(dims.y) * size_t(dims.z));
    auto cellOf = [&](const glm::vec3& p) {
        return glm::clamp(glm::ivec3(glm::floor((p - all.min) / cellSize)), glm::ivec3(0),
                          dims - 1);
    };
    auto addBox = [&](const glm::vec3& lo, const glm::vec3& hi) {
        const glm::ivec3 a = cellOf(lo), b = cellOf(hi);
        for (int z = a.z; z <= b.z; ++z)
            for (int y = a.y; y <= b.y; ++y)
                for (int x = a.x; x <= b.x; ++x) {
                    const glm::vec3 cellLo = all.min + glm::vec3(x, y, z) * cellSize;
                    Bounds& c = cells[(size_t(z) * size_t(dims.y) + size_t(y)) * size_t(dims.x) +
                                      size_t(x)];
                    c.add(glm::max(lo, cellLo));
                    c.add(glm::min(hi, cellLo + cellSize));
                }
    };
    for (const Primitive& p : mesh.primitives) {
        if (p.indexCount < 3) {
            for (uint32_t v = p.firstVertex; v < p.firstVertex + p.vertexCount; ++v)
                addBox(mesh.vertices[v].position, mesh.vertices[v].position);
            continue;
        }
        for (uint32_t t = p.firstIndex; t + 2 < p.firstIndex + p.indexCount; t += 3) {
            Bounds tri;
            for (uint32_t k = 0; k < 3; ++k) tri.add(mesh.vertices[mesh.indices[t + k]].position);
            addBox(tri.min, tri.max);
        }
    }
    std::vector<BoundingBoxes> out;
    for (const Bounds& c : cells) {
        if (c.empty()) continue;
        BoundingBoxes b;
        b.outer.center = 0.5f * (c.min + c.max);
        b.outer.halfExtents = glm::max(0.5f * (c.max - c.min), glm::vec3(minHalfExtent));
        out.push_back(b);
    }
    return out;
}

}  // namespace host
