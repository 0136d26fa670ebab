#pragma once

#include <span>
#include <vector>

#include "gauss_kronrod.h"
#include "interval.h"
#include "light.h"
#include "medium.h"
#include "ray.h"

namespace ls::ref {

// The in-scattering integrand of docs/model.md at distance s along the ray, before visibility:
// T(s) m(x) P(t(s)) Irr(x) at x = C + s v, which is exp(-betaT s) P(t(s)) Irr(x) when m = 1. The
// ray's direction must be unit length.
[[nodiscard]] glm::dvec3 inscatterIntegrand(const Medium& medium, const Light& light,
                                            const Ray& ray, double s);

// Where integrateInscatter splits the lit intervals (normalised, of a ray with a unit direction)
// before its adaptive rule: the light's features (lightFeatureDistances), the medium's
// (densityFeatureDistances) when m varies, and a geometric mesh from each interval's start of first
// step 1 / (16 betaT max(m)) for the extinction. For callers that multiply the integrand by a
// factor of their own and add its cuts.
[[nodiscard]] std::vector<double> inscatterBreakpoints(const Medium& medium, const Light& light,
                                                       const Ray& ray,
                                                       std::span<const Interval> lit);

// Lin of docs/model.md for one ray by adaptive quadrature, with V = 1 on the union of the lit
// intervals (distances from the camera; clipped to [0, S]) and 0 elsewhere. The direction is
// normalised here; a zero or NaN direction, or S <= 0, infinite or NaN, gives 0.
[[nodiscard]] QuadResult integrateInscatter(const Medium& medium, const Light& light,
                                            const Ray& ray, std::span<const Interval> lit,
                                            const QuadOptions& options = {});

// The same with the whole ray lit (no shadows).
[[nodiscard]] QuadResult integrateInscatter(const Medium& medium, const Light& light,
                                            const Ray& ray, const QuadOptions& options = {});

}  // namespace ls::ref
