#pragma once
// Two unit directions across a spot's axis, at right angles to it and to each other, in double
// precision: the frame its cone's pyramids and frusta are built in (beam_tree's light frustum,
// planes' pyramids). The helper direction is up unless the axis nearly is.
#include <glm/glm.hpp>

#include <cmath>

namespace ls {

struct AcrossAxis {
    glm::dvec3 right, up;
};

// `axis` of unit length.
inline AcrossAxis acrossAxis(const glm::dvec3& axis) {
    const glm::dvec3 helper = std::fabs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 right = glm::normalize(glm::cross(axis, helper));
    return {right, glm::cross(right, axis)};
}

}  // namespace ls
