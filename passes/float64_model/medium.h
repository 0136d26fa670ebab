#pragma once

#include <glm/vec3.hpp>

namespace ls::ref {

// The homogeneous single-scattering medium of docs/model.md. Coefficients are per colour channel,
// in 1/m.
struct Medium {
    // Unscoped so that both Medium::Isotropic and Medium::Phase::Isotropic read naturally.
    enum Phase { CornetteShanks, Isotropic };

    glm::dvec3 betaR{0.0};   // Rayleigh scattering
    glm::dvec3 betaM{0.0};   // Mie scattering
    glm::dvec3 sigmaA{0.0};  // absorption
    double g = 0.0;          // Mie asymmetry, in (-1, 1); ignored by the isotropic lobe
    Phase miePhase = CornetteShanks;
    double maxDistance = 1.0e4;  // S of sky pixels when the far plane is infinite (metres)

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

inline constexpr double kPi = 3.141592653589793238462643383279502884;
inline constexpr double kIsotropicPhase = 1.0 / (4.0 * kPi);

}  // namespace ls::ref
