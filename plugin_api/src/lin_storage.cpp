#include "lin_storage.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace lightscatter::detail {
namespace {

constexpr double kPi = 3.14159265358979;
constexpr double kStoredPeak = 16384.0;  // float16 holds 65504

// Cornette-Shanks' peak as the shaders evaluate it: at cos = +-1 (the side g points to), with
// their floor of 1e-6 on 1 + g^2 - 2 g cos.
double miePeak(const ls::MediumParams& m) {
    if (m.phase == ls::MiePhase::Isotropic) return 1.0 / (4.0 * kPi);
    if (m.phase == ls::MiePhase::Hazy) return 10.0 / (8.0 * kPi);
    const double g = m.g, g2 = g * g;
    const double denom = std::max(1.0 + g2 - 2.0 * std::fabs(g), 1e-6);
    return 3.0 * (1.0 - g2) * 2.0 / (8.0 * kPi * (2.0 + g2) * denom * std::sqrt(denom));
}

}  // namespace

float linStorageScale(const ls::LightSetup& s, const ls::MethodUnit& method) {
    const ls::MediumParams& m = s.medium;
    const double pR = 3.0 / (8.0 * kPi), pM = miePeak(m);
    // Light reaching the camera from a point or spot light has travelled at least the distance
    // between the two (the triangle inequality), through the medium.
    const glm::dvec3 camera(glm::inverse(glm::dmat4(s.camera.view))[3]);
    const double apart = s.light.kind == ls::LightType::Directional
                             ? 0.0
                             : glm::length(camera - glm::dvec3(s.light.position));
    double bound = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double betaR = m.betaR[c], betaM = m.betaM[c], betaT = double(m.betaT()[c]);
        const double scatter = betaR * pR + betaM * pM;  // 1/(m sr)
        if (!(scatter > 0.0)) continue;
        const double I = s.light.intensity[c];
        double lin = 0.0;
        if (ls::simplifiedModel(s)) {
            const double a1 = s.settings.simplifiedA1;
            const double w = std::sqrt(std::max(double(s.settings.simplifiedA0) / a1, 1e-12));
            lin = I * (betaR + betaM) * kPi / (4.0 * kPi * a1 * w);
        } else if (s.light.kind == ls::LightType::Directional) {
            lin = I * scatter / betaT;
        } else {
            const double r0 = std::max(double(s.light.radius), 1e-6);
            lin = I * scatter * (kPi / r0 + double(method.ambient(s)) / betaT);
        }
        // A non-uniform medium scatters up to maxDensity() times as much at a point, and may be
        // clear between the light and the camera. A directional light's bound holds as it is:
        // the integral of m T along a ray is (1 - T) / betaT whatever m is.
        if (m.nonUniform() && s.light.kind != ls::LightType::Directional)
            lin *= double(m.maxDensity());
        else if (!ls::simplifiedModel(s))
            lin *= std::exp(-betaT * apart);
        bound = std::max(bound, lin);
    }
    if (!(bound > kStoredPeak)) return 1.0f;
    const int k = static_cast<int>(std::ceil(std::log2(bound / kStoredPeak)));
    return std::ldexp(1.0f, -k);
}

}  // namespace lightscatter::detail
