#pragma once

#include <functional>
#include <span>

#include <glm/vec3.hpp>

#include "interval.h"

namespace ls::ref {

struct QuadOptions {
    double relTol = 1e-10;  // per channel, relative to that channel's integral
    double absTol = 0.0;    // per channel; lets a channel whose integral is ~0 stop early
    int maxSegments = 20000;
};

struct QuadResult {
    glm::dvec3 value{0.0};
    glm::dvec3 error{0.0};  // sum of |K15 - G7| over the final segments: a pessimistic bound
    int evaluations = 0;
    bool converged = true;
};

using Integrand = std::function<glm::dvec3(double)>;

// Adaptive Gauss-Kronrod (G7-K15) quadrature of a vector integrand over a union of pieces.
// The pieces' ends are where the caller knows the integrand is not smooth (discontinuities, peaks,
// scale changes): the rule samples only inside a segment, so a feature at an end is never missed
// and never sampled. The segment with the largest relative error is bisected until every channel
// meets max(relTol |I|, absTol) or maxSegments is reached (then converged is false).
[[nodiscard]] QuadResult integrateAdaptive(const Integrand& f, std::span<const Interval> pieces,
                                           const QuadOptions& options = {});

}  // namespace ls::ref
