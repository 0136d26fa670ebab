#pragma once
// The order seed 004's beam tree needs its polygons in: front to back as seen from the light, none
// crossing another. A distance sort is not such an order (nearest point: a box standing on a floor
// far from the light is farther than the floor's nearest point, yet hides part of the floor, and
// inserted after the floor it would be lost and its shadow taken for lit space). A BSP tree of the
// polygons (autopartition, largest polygons first as splitters, since a floor or wall then cuts
// nothing) traversed from the light gives an exact order, splitting the polygons that
// interpenetrate: the way seed 004 (chapter 6) names to lift its restriction to outer boxes that do
// not overlap.
#include <vector>

#include "polygon.h"

namespace ls::beam {

// `polygons` (convex, planar) reordered front to back from `eye`, cut where one's plane crosses
// another; `epsilon` is the planes' thickness. Polygons seen edge-on may come in either order.
std::vector<Polygon> frontToBack(std::vector<Polygon> polygons, const glm::dvec3& eye,
                                 double epsilon);

}  // namespace ls::beam
