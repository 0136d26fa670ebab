#pragma once

#include <span>

#include <glm/vec3.hpp>

#include "interval.h"
#include "light.h"
#include "medium.h"
#include "ray.h"

namespace ls::ref {

// Integral of exp(-beta s) over [a, b] (0 when b <= a), for beta >= 0: exp(-beta a) times
// -expm1(-beta (b - a)) / beta, or a series where beta (b - a) is tiny (beta = 0 gives b - a).
// This is docs/model.md's safe form; exp(-beta a) - exp(-beta b) loses most digits in thin media.
[[nodiscard]] double attenuatedLength(double beta, double a, double b);
[[nodiscard]] glm::dvec3 attenuatedLength(const glm::dvec3& beta, double a, double b);

// Directional light, no shadows (Hoffman-Preetham): E P(t) (1 - exp(-betaT S)) / betaT, S in a
// channel where betaT is 0. Throws std::invalid_argument unless the light is directional.
[[nodiscard]] glm::dvec3 directionalClosedForm(const Medium& medium, const Light& light,
                                               const Ray& ray);

// Directional light with V = 1 on the union of the lit intervals (camera distances, clipped to
// [0, S]): E P(t) sum over them of the integral of exp(-betaT s). Where m varies, a run [a, b]
// gives E P(t) T(a) (-expm1(-betaT dtau)) / betaT (dtau in a channel where betaT is 0), dtau the
// optical depth of [a, b] (docs/model.md): exact too, since dT/ds = -betaT m T.
[[nodiscard]] glm::dvec3 directionalClosedForm(const Medium& medium, const Light& light,
                                               const Ray& ray, std::span<const Interval> lit);

// Integral over s in [0, length] of 1 / ((s + b)^2 + w^2), w > 0, as
// (atan((length + b)/w) - atan(b/w)) / w evaluated without cancellation: where both ends lie on
// the same side of the light's projection the difference of arctangents is folded into one
// atan2 (otherwise a light far behind the camera would subtract two values near pi/2).
[[nodiscard]] double arctanIntegral(double b, double w, double length);

// Seed 001's closed form with r0: Lin = I betaS / (4 pi) (atan((S + b)/w) - atan(b/w)) / w,
// q = C - L, b = dot(v, q), w^2 = |cross(v, q)|^2 + r0^2.
// It is the model's integral exactly when (1) the total phase is isotropic, i.e. betaR = 0 and
// miePhase == Isotropic, so P(t) = betaM / (4 pi) and betaS = betaM; and (2) there is no
// extinction, betaT = 0 (the exp terms are dropped; with betaT > 0 it over-estimates Lin by a
// relative amount at most betaT (S + |q| + S)). Condition (1) is checked: std::invalid_argument
// otherwise, for directional lights, and for a medium whose m is not 1. Spot lights are limited to
// their cone and range.
[[nodiscard]] glm::dvec3 pointArctanClosedForm(const Medium& medium, const Light& light,
                                               const Ray& ray);
[[nodiscard]] glm::dvec3 pointArctanClosedForm(const Medium& medium, const Light& light,
                                               const Ray& ray, std::span<const Interval> lit);

// Seed 004's simplified light model (2.12-2.17): irradiance I / (a1 r^2 + a0) with no transmittance
// anywhere, an isotropic phase 1/(4 pi), and betaS = betaR + betaM; a spot lights its cone within
// its range (the seed's cone intersection), V = 1 on `lit`. Its closed form (2.17) is
// betaS I / (4 pi a1) times the arctangent integral with w^2 = h^2 + a0 / a1, h the ray's distance
// from the light. a1 = 1, a0 = r0^2 is seed 001's closed form with the model's r0. Throws
// std::invalid_argument for a directional light, a1 <= 0, a0 < 0 or a medium whose m is not 1.
[[nodiscard]] glm::dvec3 simplifiedClosedForm(const Medium& medium, const Light& light,
                                              const Ray& ray, double a0, double a1);
[[nodiscard]] glm::dvec3 simplifiedClosedForm(const Medium& medium, const Light& light,
                                              const Ray& ray, std::span<const Interval> lit,
                                              double a0, double a1);

}  // namespace ls::ref
