#pragma once

#include <span>

#include "gauss_kronrod.h"
#include "interval.h"
#include "light.h"
#include "medium.h"
#include "ray.h"

namespace ls::ref {

// The in-scattering integrand of docs/model.md at distance s along the ray, before visibility:
// exp(-betaT s) P(t(s)) Irr(C + s v). The ray's direction must be unit length.
[[nodiscard]] glm::dvec3 inscatterIntegrand(const Medium& medium, const Light& light,
                                            const Ray& ray, double s);

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
