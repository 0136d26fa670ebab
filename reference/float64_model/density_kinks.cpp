#include "density_kinks.h"

#include <cmath>

#include "box_crossings.h"
#include "ray_geometry.h"

namespace ls::ref {

std::vector<double> densityFeatureDistances(const Density& density, const Ray& ray) {
    std::vector<double> points;
    if (density.heightFog && ray.direction.y != 0.0 && density.base > 0.0) {
        const double h0 = density.heightFog->baseHeight;
        const double dy = ray.direction.y;
        const double crossing = (h0 - ray.origin.y) / dy;
        points.push_back(crossing);
        // Above h0 the factor is exp(-k |dy| u) at u metres from the lowest point of the part of
        // [0, S] above it: the crossing, or the ray's lower end when the whole ray is above.
        const double k = density.heightFog->falloff;
        const double lowEnd = dy > 0.0 ? 0.0 : ray.length;
        const bool crosses = crossing > 0.0 && crossing < ray.length;
        if (k > 0.0 && (crosses || ray.origin.y + lowEnd * dy > h0)) {
            const double first = 1.0 / (16.0 * k * std::abs(dy));
            appendGeometricMesh(points, crosses ? crossing : lowEnd, first, dy > 0.0 ? 1.0 : -1.0,
                                0.0, ray.length);
        }
    }
    for (const FogBox& box : density.volumes) {
        if (!(box.density > 0.0)) continue;
        const std::vector<double> kinks = boxWeightKinks(box, ray.origin, ray.direction);
        points.insert(points.end(), kinks.begin(), kinks.end());
    }
    return points;
}

}  // namespace ls::ref
