#pragma once
// Brute-force integrals of the non-uniform medium for the tests: dense midpoint rules over m(x)
// sampled point by point, sharing nothing with the model's closed forms, kink lists or adaptive
// quadrature. Each rule is split where the test knows the integrand jumps (every plane of the
// medium: base height, box faces, fade and centre planes; and the light's own ends), so that its
// error is the midpoint rule's O(h^2) and not the O(h) a jump between two samples would cost.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include "float64_model/density.h"
#include "float64_model/interval.h"
#include "float64_model/light.h"
#include "float64_model/medium.h"
#include "float64_model/ray.h"
#include "float64_model/ray_geometry.h"

namespace ls::ref::test {

// The t in (lo, hi) where origin + t dir crosses any plane of the medium; with lo and hi, sorted.
inline std::vector<double> planeCrossings(const Density& d, const glm::dvec3& origin,
                                          const glm::dvec3& dir, double lo, double hi) {
    std::vector<double> t{lo, hi};
    auto plane = [&](const glm::dvec3& normal, double offset) {  // dot(normal, x) = offset
        const double rate = glm::dot(normal, dir);
        if (rate == 0.0) return;
        const double at = (offset - glm::dot(normal, origin)) / rate;
        if (at > lo && at < hi) t.push_back(at);
    };
    if (d.heightFog) plane({0.0, 1.0, 0.0}, d.heightFog->baseHeight);
    for (const FogBox& b : d.volumes) {
        for (int j = 0; j < 3; ++j) {
            const double c = glm::dot(b.axes[j], b.center), a = b.halfExtents[j];
            for (double offset : {-a, a, -(a - b.fade), a - b.fade, 0.0})
                plane(b.axes[j], c + offset);
        }
    }
    std::sort(t.begin(), t.end());
    return t;
}

// Midpoint rule for the integral of m over t in [lo, hi] of origin + t dir (dir unit), with
// `panels` panels spread over the pieces between plane crossings in proportion to their length.
inline double bruteOpticalDepth(const Density& d, const glm::dvec3& origin, const glm::dvec3& dir,
                                double lo, double hi, int panels) {
    if (!(hi > lo)) return 0.0;
    const std::vector<double> cuts = planeCrossings(d, origin, dir, lo, hi);
    // A long double sum: 1e5 and more terms would otherwise round the total by 1e-11.
    long double sum = 0.0L;
    for (std::size_t i = 1; i < cuts.size(); ++i) {
        const double a = cuts[i - 1], b = cuts[i];
        const int n = std::max(1, static_cast<int>(std::ceil(panels * (b - a) / (hi - lo))));
        const double h = (b - a) / n;
        for (int k = 0; k < n; ++k) sum += d.at(origin + (a + (k + 0.5) * h) * dir) * h;
    }
    return static_cast<double>(sum);
}

inline double bruteOpticalDepth(const Density& d, const glm::dvec3& from, const glm::dvec3& to,
                                int panels) {
    const double length = glm::length(to - from);
    if (!(length > 0.0)) return 0.0;
    return bruteOpticalDepth(d, from, (to - from) / length, 0.0, length, panels);
}

// Lin of docs/model.md with the medium's density, V = 1 inside the light's volume: a midpoint rule
// over s with `panels` panels on the ray, T(s) from a running sum of m over them, and for point and
// spot lights the optical depth to the light by a midpoint rule of `lightPanels` panels. The
// light's geometry (r^2 + r0^2, cone, falloff) is the model's irradiance in a clear medium: only
// the medium is brute-forced here.
inline glm::dvec3 bruteInscatter(const Medium& medium, const Light& light, const Ray& ray,
                                 int panels, int lightPanels) {
    Medium clear = medium;
    clear.betaR = clear.betaM = clear.sigmaA = glm::dvec3(0.0);
    clear.density = Density{};
    const glm::dvec3 beta = medium.betaT();
    const Density& d = medium.density;
    std::vector<double> cuts = planeCrossings(d, ray.origin, ray.direction, 0.0, ray.length);
    for (const Interval& in : spotLitIntervals(light, ray)) {
        cuts.push_back(in.begin);
        cuts.push_back(in.end);
    }
    std::sort(cuts.begin(), cuts.end());
    glm::dvec3 sum(0.0);
    double tau = 0.0;  // at the current panel's start
    for (std::size_t i = 1; i < cuts.size(); ++i) {
        const double a = cuts[i - 1], b = cuts[i];
        if (!(b > a)) continue;
        const int n = std::max(1, static_cast<int>(std::ceil(panels * (b - a) / ray.length)));
        const double h = (b - a) / n;
        for (int k = 0; k < n; ++k) {
            const glm::dvec3 x = ray.origin + (a + (k + 0.5) * h) * ray.direction;
            const double m = d.at(x);
            const glm::dvec3 T = glm::exp(-beta * (tau + 0.5 * h * m));
            tau += h * m;
            glm::dvec3 irr = irradiance(light, clear, x);
            if (light.type != Light::Directional && irr != glm::dvec3(0.0))
                irr *= glm::exp(-beta * bruteOpticalDepth(d, x, light.position, lightPanels));
            sum += T * m * medium.P(cosTheta(light, ray.direction, x)) * irr * h;
        }
    }
    return sum;
}

}  // namespace ls::ref::test
