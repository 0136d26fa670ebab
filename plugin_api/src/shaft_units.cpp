// The intensity a light needs for a shaft of a chosen brightness (shaftIntensity in
// lightscatter.h): docs/model.md's single scattering across a beam, the irradiance taken as
// constant over the beam's width.
#include <cmath>
#include <numbers>
#include <string>

#include <lightscatter/lightscatter.h>
#include "enum_checks.h"
#include "field_checks.h"

namespace lightscatter {
namespace {

constexpr double kPi = std::numbers::pi;

// P(t)/betaS's parts: the Rayleigh and Mie phase functions at the scattering angle (docs/model.md).
double rayleighPhase(double c) {
    return 3.0 * (1.0 + c * c) / (16.0 * kPi);
}
double miePhase(const Medium& m, double c) {
    if (m.phase == MiePhase::Isotropic) return 1.0 / (4.0 * kPi);
    if (m.phase == MiePhase::Hazy)
        return (1.0 + 9.0 * std::pow((1.0 + c) / 2.0, 8.0)) / (8.0 * kPi);
    const double g = m.g;
    return 3.0 * (1.0 - g * g) * (1.0 + c * c) /
           (8.0 * kPi * (2.0 + g * g) * std::pow(1.0 + g * g - 2.0 * g * c, 1.5));
}

double positive(float v, const char* field, bool zeroAllowed = false) {
    if (!std::isfinite(v) || v < 0.0f || (!zeroAllowed && v == 0.0f))
        detail::fail(std::string("shaftIntensity: goal.") + field + " = " + detail::num(v) +
                     (zeroAllowed ? ": must be finite and >= 0" : ": must be finite and > 0"));
    return v;
}

}  // namespace

Vec3 shaftIntensity(LightType type, const Medium& medium, const ShaftGoal& goal) {
    detail::checkLightType(type, "shaftIntensity: type");
    detail::checkMiePhase(medium.phase, "shaftIntensity: medium.phase");
    const double brightness = positive(goal.brightness, "brightness");
    const double width = positive(goal.beamWidth, "beamWidth");
    const double view = positive(goal.viewDistance, "viewDistance", true);
    const double light =
        positive(goal.lightDistance, "lightDistance", type == LightType::Directional);
    const double radius = positive(goal.radius, "radius");
    if (!(goal.scatteringAngleDegrees >= 0.0f && goal.scatteringAngleDegrees <= 180.0f))
        detail::fail("shaftIntensity: goal.scatteringAngleDegrees = " +
                     detail::num(goal.scatteringAngleDegrees) + ": must be in [0, 180]");
    const double c = std::cos(double(goal.scatteringAngleDegrees) * kPi / 180.0);
    Vec3 out{};
    for (int k = 0; k < 3; ++k) {
        const double betaR = medium.betaR[k], betaM = medium.betaM[k];
        const double betaT = betaR + betaM + medium.sigmaA[k];
        const double scattering = betaR * rayleighPhase(c) + betaM * miePhase(medium, c);
        if (!(scattering > 0.0))
            detail::fail("shaftIntensity: the medium scatters nothing in channel " +
                         std::to_string(k) +
                         " (betaR and betaM are 0): no intensity makes a shaft");
        // The beam's width: (1 - exp(-betaT w)) / betaT, w where nothing extinguishes.
        const double across = betaT > 0.0 ? -std::expm1(-betaT * width) / betaT : width;
        // Per unit of irradiance at the shaft, what reaches the camera.
        const double perIrradiance = scattering * across * std::exp(-betaT * view);
        // Irradiance per unit of the light's intensity at the shaft.
        const double irradiance =
            type == LightType::Directional
                ? 1.0
                : std::exp(-betaT * light) / (light * light + radius * radius);
        const double needed = brightness / (perIrradiance * irradiance);
        if (!(needed <= limits::kMaxIntensity))
            detail::fail("shaftIntensity: a shaft of brightness " + detail::num(goal.brightness) +
                         " needs an intensity of " + detail::num(float(needed)) + " in channel " +
                         std::to_string(k) + ", above limits::kMaxIntensity (" +
                         detail::num(limits::kMaxIntensity) +
                         "): the medium scatters too little over this width, or extinguishes too "
                         "much over these distances");
        out[k] = float(needed);
    }
    return out;
}

}  // namespace lightscatter
