#include "medium.h"

#include <algorithm>
#include <cmath>

namespace ls::ref {

glm::dvec3 Medium::betaT() const {
    return betaR + betaM + sigmaA;
}

double Medium::pR(double cosTheta) {
    return 3.0 / (16.0 * kPi) * (1.0 + cosTheta * cosTheta);
}

double phaseCornetteShanks(double cosTheta, double g) {
    const double g2 = g * g;
    // 1 + g^2 - 2 g c >= (1 - |g|)^2 > 0 for |g| < 1, so the power never sees a negative base.
    const double denom = 1.0 + g2 - 2.0 * g * cosTheta;
    return kIsotropicPhase * 3.0 * (1.0 - g2) / (2.0 * (2.0 + g2)) * (1.0 + cosTheta * cosTheta) /
           (denom * std::sqrt(denom));
}

double phaseHazy(double cosTheta) {
    const double h = 0.5 * (1.0 + cosTheta);
    const double h2 = h * h, h4 = h2 * h2;
    return kHazyK * (1.0 + 9.0 * h4 * h4);
}

double Medium::pM(double cosTheta) const {
    switch (miePhase) {
        case Isotropic:
            return kIsotropicPhase;
        case Hazy:
            return phaseHazy(cosTheta);
        case CornetteShanks:
            break;
    }
    return phaseCornetteShanks(cosTheta, g);
}

glm::dvec3 Medium::P(double cosTheta) const {
    return betaR * pR(cosTheta) + betaM * pM(cosTheta);
}

glm::dvec3 Medium::maxP() const {
    // Both lobes are largest at cos = +1 or -1 (Cornette-Shanks has only a minimum inside), so the
    // larger end value bounds each lobe; taking it per lobe keeps the bound valid for any betas.
    const double r = pR(1.0);
    const double m = std::max(pM(1.0), pM(-1.0));
    return betaR * r + betaM * m;
}

}  // namespace ls::ref
