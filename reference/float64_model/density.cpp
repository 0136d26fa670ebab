#include "density.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace ls::ref {

glm::dvec3 FogBox::local(const glm::dvec3& x) const {
    const glm::dvec3 d = x - center;
    return {glm::dot(d, axes[0]), glm::dot(d, axes[1]), glm::dot(d, axes[2])};
}

double FogBox::weight(const glm::dvec3& x) const {
    const glm::dvec3 p = local(x);
    double w = 1.0;
    for (int j = 0; j < 3; ++j) {
        const double inside = halfExtents[j] - std::abs(p[j]);
        if (fade > 0.0) {
            w *= std::clamp(inside / fade, 0.0, 1.0);
        } else if (!(inside >= 0.0)) {
            return 0.0;
        }
    }
    return w;
}

double Density::at(const glm::dvec3& x) const {
    double m = base;
    if (heightFog) m *= std::exp(-heightFog->falloff * std::max(0.0, x.y - heightFog->baseHeight));
    for (const FogBox& box : volumes) m += box.density * box.weight(x);
    return m;
}

double Density::maxDensity() const {
    double m = base;
    for (const FogBox& box : volumes) m += box.density;
    return m;
}

}  // namespace ls::ref
