#include "bounding_boxes.h"

#include <cmath>

namespace host {

std::vector<BoundingBoxes> boundingBoxes(const MeshData& mesh, float minHalfExtent) {
    std::vector<BoundingBoxes> out;
    for (const Primitive& p : mesh.primitives) {
        if (p.vertexCount == 0) continue;
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (uint32_t i = 0; i < p.vertexCount; ++i) {
            const glm::vec3 local =
                glm::transpose(p.axes) * mesh.vertices[p.firstVertex + i].position;
            lo = glm::min(lo, local);
            hi = glm::max(hi, local);
        }
        BoundingBoxes b;
        b.outer.axes = p.axes;
        b.outer.center = p.axes * (0.5f * (lo + hi));
        b.outer.halfExtents = glm::max(0.5f * (hi - lo), glm::vec3(minHalfExtent));
        // A solid box: every vertex at one of the box's corners (to a millimetre).
        const glm::vec3 half = 0.5f * (hi - lo);
        bool box = glm::all(glm::greaterThan(half, glm::vec3(2.0f * minHalfExtent)));
        for (uint32_t i = 0; box && i < p.vertexCount; ++i) {
            const glm::vec3 local =
                glm::transpose(p.axes) * mesh.vertices[p.firstVertex + i].position;
            const glm::vec3 d = glm::abs(local - 0.5f * (lo + hi)) - half;
            box = glm::all(glm::lessThan(glm::abs(d), glm::vec3(1e-3f)));
        }
        if (box) {
            OrientedBox inner = b.outer;
            inner.halfExtents = half - glm::vec3(minHalfExtent);
            b.inner = inner;
        }
        out.push_back(b);
    }
    return out;
}

}  // namespace host
