#pragma once
// Occluders for seed 004's methods from a scene's triangles: one oriented box per glTF primitive,
// on its node's axes, enclosing its vertices; and an inner box where the primitive is itself a
// solid box (every vertex at a corner of that box), the same box shrunk by a millimetre.
#include <optional>
#include <vector>

#include "scene.h"

namespace host {

struct OrientedBox {
    glm::vec3 center{0.0f};
    glm::mat3 axes{1.0f};
    glm::vec3 halfExtents{0.0f};
};

struct BoundingBoxes {
    OrientedBox outer;
    std::optional<OrientedBox> inner;
};

// Boxes thinner than `minHalfExtent` along an axis (a flat quad) get that half-extent, so that
// every box has a volume.
std::vector<BoundingBoxes> boundingBoxes(const MeshData& mesh, float minHalfExtent = 1e-3f);

}  // namespace host
