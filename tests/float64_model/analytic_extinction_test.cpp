// How much seed 001's closed form loses by ignoring extinction, measured against the model's
// integral: a 48x48 view with a point light in it, for camera-light distances d and optical depths
// tau = betaT d. The image's relative error (sum |a - b| / sum b) grows like tau; the `auto`
// method uses the closed form only below the threshold this test holds to 1%.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "float64_model/closed_forms.h"
#include "float64_model/inscatter_integral.h"

namespace ls::ref {
namespace {

// The image error of the closed form for a view 1.5 d long, the light at distance d ahead and
// `offset` d off the axis, with extinction betaT = tau / d (all of it Mie, isotropic).
double imageError(double d, double tau, double offset) {
    Medium medium;
    medium.betaM = glm::dvec3(tau / d);
    medium.miePhase = Medium::Isotropic;
    Light light;
    light.type = Light::Point;
    light.position = {offset * d, 0.0, -d};
    light.intensity = glm::dvec3(1.0);
    const int n = 48;
    const double tanHalf = std::tan(0.5 * 60.0 * kPi / 180.0);
    double diff = 0.0, sum = 0.0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const glm::dvec3 dir =
                glm::normalize(glm::dvec3((2.0 * (x + 0.5) / n - 1.0) * tanHalf,
                                          (2.0 * (y + 0.5) / n - 1.0) * tanHalf, -1.0));
            const Ray ray{{0.0, 0.0, 0.0}, dir, 1.5 * d / -dir.z};
            const double exact = integrateInscatter(medium, light, ray).value.x;
            const double closed = pointArctanClosedForm(medium, light, ray).x;
            diff += std::fabs(closed - exact);
            sum += exact;
        }
    return diff / sum;
}

}  // namespace

TEST(AnalyticExtinction, TheClosedFormStaysWithinOnePercentBelowTheAutoThreshold) {
    // kAnalyticMaxOpticalDepth in plugin_api/src/method_choice.cpp.
    const double threshold = 0.007;
    std::printf("%8s %6s %8s %12s\n", "d (m)", "offset", "tau", "image error");
    for (double d : {2.0, 20.0, 200.0})
        for (double offset : {0.0, 0.4})
            for (double tau : {0.001, threshold, 0.01, 0.03}) {
                const double e = imageError(d, tau, offset);
                std::printf("%8.1f %6.1f %8.4f %11.3f%%\n", d, offset, tau, 100.0 * e);
                if (tau <= threshold) {
                    EXPECT_LT(e, 0.01) << "d " << d << " tau " << tau;
                }
                if (tau >= 0.03) {
                    EXPECT_GT(e, 0.01) << "the error must grow with tau";
                }
            }
}

}  // namespace ls::ref
