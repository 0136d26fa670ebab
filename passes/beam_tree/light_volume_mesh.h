#pragma once
// Triangles the GPU draws for seed 004's hybrid method, from a light volume's beam tree (plain
// C++): the surfaces of the fully lit pyramids (chapter 3.2: each visible polygon with the light as
// apex; every triangle wound counter-clockwise seen from outside its pyramid, so that a
// rasterizer's front faces are where a view ray enters the lit volume), and the parts of sampling
// polygons that lie in uncertain space (5.4).
#include <glm/glm.hpp>

#include <vector>

#include "beam_tree.h"

namespace ls::beam {

// Appends the lit pyramids' triangles (three points each) to `out`.
void appendLitPyramids(const BeamTree& tree, std::vector<glm::vec4>& out);

// Appends the triangles of the parts of `polygon` that are uncertain (and, with `lit`, those that
// are lit) to `out`. Unlit and outside parts are dropped.
void appendPartitioned(const BeamTree& tree, const Polygon& polygon,
                       std::vector<glm::vec4>& uncertain, std::vector<glm::vec4>* lit = nullptr);

}  // namespace ls::beam
