#pragma once
// Seed 004, 5.1-5.2: a light's volume classified from occluders' bounding volumes. Oriented boxes
// stand for the objects: the outer box encloses an object, the optional inner box lies inside it.
// The light-facing faces of the outer boxes, front to back, build the beam tree; the inner boxes'
// light-facing faces become stoppers; the far polygon closes the light's frustum.
#include <optional>
#include <vector>

#include "beam_tree.h"

namespace ls::beam {

struct OrientedBox {
    glm::dvec3 center{0.0};
    glm::dmat3 axes{1.0};  // unit columns
    glm::dvec3 halfExtents{0.5};
};

struct Occluder {
    OrientedBox outer;
    std::optional<OrientedBox> inner;
};

// The faces of a box whose outside faces `light` (at most three), counter-clockwise seen from
// outside.
std::vector<Polygon> lightFacingFaces(const OrientedBox& box, const glm::dvec3& light);

// The light's frustum: walls through the light (none for a point light) and its far polygon.
struct LightFrustum {
    glm::dvec3 position{0.0};
    std::vector<Plane> walls;
    Polygon far;  // empty: no backplate
};
// A spot of half-angle `halfAngle` (radians) along unit `axis`, cut at `range` along the axis: the
// four walls around its cone (seed 004's footnote) and the square far polygon.
LightFrustum spotFrustum(const glm::dvec3& position, const glm::dvec3& axis, double halfAngle,
                         double range);

struct LightVolume {
    BeamTree tree;
    size_t outerPolygons = 0, stopperPolygons = 0;
};

// Builds the tree: the outer boxes' light-facing faces front to back from the light (a BSP order,
// front_to_back.h, so boxes may overlap and a box is never lost behind a farther box's face), then
// the backplate, then the inner boxes' faces as stoppers, front to back too. An outer box that
// holds the light makes all of the light's volume uncertain.
LightVolume buildLightVolume(const LightFrustum& frustum, const std::vector<Occluder>& occluders,
                             double epsilon = 1e-3);

}  // namespace ls::beam
