#pragma once

#include <glm/vec3.hpp>

#include "density.h"

namespace ls::ref {

// The single-scattering medium of docs/model.md. Coefficients are per colour channel, in 1/m, those
// of density factor 1: the factor m(x) multiplies all three at x.
struct Medium {
    // Unscoped so that both Medium::Isotropic and Medium::Phase::Isotropic read naturally.
    enum Phase { CornetteShanks, Isotropic, Hazy };

    glm::dvec3 betaR{0.0};   // Rayleigh scattering
    glm::dvec3 betaM{0.0};   // Mie scattering
    glm::dvec3 sigmaA{0.0};  // absorption
    double g = 0.0;          // Mie asymmetry, in (-1, 1); ignored by the isotropic lobe
    Phase miePhase = CornetteShanks;
    double maxDistance = 1.0e4;  // S of sky pixels when the far plane is infinite (metres)
    // m(x). The default, m = 1, is the homogeneous medium: every formula then takes its own path,
    // as it did before the medium could vary, and gives the same numbers bit for bit.
    Density density;

    // Extinction betaR + betaM + sigmaA.
    [[nodiscard]] glm::dvec3 betaT() const;
    // Rayleigh phase function, 1/sr.
    [[nodiscard]] static double pR(double cosTheta);
    // The Mie lobe selected by miePhase, 1/sr. "Isotropic" replaces only this lobe.
    [[nodiscard]] double pM(double cosTheta) const;
    // betaR pR + betaM pM, 1/(m sr).
    [[nodiscard]] glm::dvec3 P(double cosTheta) const;
    // An upper bound of P over every angle, per channel (used to bound truncated tails).
    [[nodiscard]] glm::dvec3 maxP() const;
};

// Cornette-Shanks with asymmetry g, 1/sr.
[[nodiscard]] double phaseCornetteShanks(double cosTheta, double g);

// Seed 004's (after Nishita) phase function for a hazy atmosphere, K (1 + 9 cos^16(alpha / 2)),
// 1/sr, with cos^16(alpha / 2) = ((1 + cos alpha) / 2)^8 and K = 1 / (8 pi): over the sphere 2 pi
// integral_{-1}^{1} ((1 + x) / 2)^8 dx = 4 pi / 9, so the integral of p is K (4 pi + 4 pi) = 1.
[[nodiscard]] double phaseHazy(double cosTheta);
inline constexpr double kHazyK = 1.0 / (8.0 * 3.141592653589793238462643383279502884);
// The K seed 004's appendix A gives, 1 / 16.45948 (= 2^15 / (54647 pi^2)): it integrates p times
// sqrt(1 - x^2) over x, a ring's radius where the sphere's area element 2 pi dx has none, and so
// normalises to 1.527 instead of 1 (tests/float64_model/phase_test.cpp).
inline constexpr double kSeed004HazyK =
    32768.0 / (54647.0 * 9.869604401089358618834490999876151135);

inline constexpr double kPi = 3.141592653589793238462643383279502884;
inline constexpr double kIsotropicPhase = 1.0 / (4.0 * kPi);

}  // namespace ls::ref
