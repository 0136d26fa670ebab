#pragma once
// Occluders for seed 004's methods from a scene's triangles: one oriented box per connected part of
// each glTF primitive (a colonnade's pillars, a room's pieces of furniture), on its node's axes,
// enclosing the part's vertices; and an inner box where the part is itself a solid box (every
// vertex at a corner of that box), the same box shrunk by a millimetre. Separate parts give the
// beam tree lit space between them that one box around the whole primitive would make uncertain.
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

// At most `maxBoxes` axis-aligned boxes enclosing every triangle, for a scene of more parts than
// the beam tree takes (100,000 separate triangles): the scene's bounds cut into a grid of about
// cubic cells, one box per cell that holds geometry, around what of each triangle's bounds lies in
// the cell. The boxes stay inside their cells, so no two overlap (seed 004's rule), and none is
// an inner box.
std::vector<BoundingBoxes> gridBoxes(const MeshData& mesh, size_t maxBoxes,
                                     float minHalfExtent = 1e-3f);

}  // namespace host
