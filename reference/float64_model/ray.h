#pragma once

#include <glm/vec3.hpp>

namespace ls::ref {

// A pixel's view ray: from the camera C along the unit direction v, for S metres (docs/model.md).
struct Ray {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};
    double length = 0.0;
};

}  // namespace ls::ref
