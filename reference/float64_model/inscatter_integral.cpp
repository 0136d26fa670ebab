#include "inscatter_integral.h"

#include <algorithm>
#include <optional>
#include <vector>

#include <glm/exponential.hpp>

#include "density_kinks.h"
#include "ray_geometry.h"
#include "transmittance.h"

namespace ls::ref {

glm::dvec3 inscatterIntegrand(const Medium& medium, const Light& light, const Ray& ray, double s) {
    const glm::dvec3 p = ray.origin + s * ray.direction;
    if (!medium.density.unit()) {
        // T(s) m(x) P(t) Irr(x), with both transmittances from their optical depths.
        return transmittance(medium, ray, s) * medium.density.at(p) *
               medium.P(cosTheta(light, ray.direction, p)) * irradiance(light, medium, p);
    }
    return glm::exp(-medium.betaT() * s) * medium.P(cosTheta(light, ray.direction, p)) *
           irradiance(light, medium, p);
}

std::vector<double> inscatterBreakpoints(const Medium& medium, const Light& light, const Ray& ray,
                                         std::span<const Interval> lit) {
    std::vector<double> cuts = lightFeatureDistances(light, ray);
    // exp(-betaT s) falls by e over 1/betaT: a mesh from each lit interval's start resolves it
    // however long the interval is (a dense medium over kilometres would otherwise put every
    // node of the first rule where the integrand has already vanished). Where m varies, its
    // densest point sets the shortest such length, and its own kinks end pieces too.
    const glm::dvec3 beta = medium.betaT();
    double betaMax = std::max({beta.x, beta.y, beta.z});
    if (!medium.density.unit()) {
        betaMax *= medium.density.maxDensity();
        const std::vector<double> kinks = densityFeatureDistances(medium.density, ray);
        cuts.insert(cuts.end(), kinks.begin(), kinks.end());
    }
    if (betaMax > 0.0) {
        for (const Interval& in : lit) {
            appendGeometricMesh(cuts, in.begin, 1.0 / (16.0 * betaMax), 1.0, in.begin, in.end);
        }
    }
    return cuts;
}

QuadResult integrateInscatter(const Medium& medium, const Light& light, const Ray& ray,
                              std::span<const Interval> lit, const QuadOptions& options) {
    const std::optional<Ray> maybeUnit = unitRay(ray);
    if (!maybeUnit) return {};
    const Ray& unit = *maybeUnit;
    const std::vector<Interval> lit01 = normalizeIntervals(lit, unit.length);
    if (lit01.empty()) return {};

    const std::vector<Interval> pieces =
        splitAt(lit01, inscatterBreakpoints(medium, light, unit, lit01));
    return integrateAdaptive([&](double s) { return inscatterIntegrand(medium, light, unit, s); },
                             pieces, options);
}

QuadResult integrateInscatter(const Medium& medium, const Light& light, const Ray& ray,
                              const QuadOptions& options) {
    const Interval whole{0.0, ray.length};
    return integrateInscatter(medium, light, ray, {&whole, 1}, options);
}

}  // namespace ls::ref
