#include "model_conversion.h"

#include "float64_model/closed_forms.h"
#include "float64_model/inscatter_integral.h"

#include <limits>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace plugin_test {

ls::ref::Medium refMedium(const lightscatter::Medium& m) {
    ls::ref::Medium r;
    r.betaR = {m.betaR[0], m.betaR[1], m.betaR[2]};
    r.betaM = {m.betaM[0], m.betaM[1], m.betaM[2]};
    r.sigmaA = {m.sigmaA[0], m.sigmaA[1], m.sigmaA[2]};
    r.g = m.g;
    r.miePhase = m.phase == lightscatter::MiePhase::Isotropic ? ls::ref::Medium::Isotropic
                 : m.phase == lightscatter::MiePhase::Hazy    ? ls::ref::Medium::Hazy
                                                              : ls::ref::Medium::CornetteShanks;
    r.maxDistance = m.maxDistance;
    return r;
}

ls::ref::Light refLight(const lightscatter::Light& l) {
    ls::ref::Light r;
    r.type = l.type == lightscatter::LightType::Directional ? ls::ref::Light::Directional
             : l.type == lightscatter::LightType::Spot      ? ls::ref::Light::Spot
                                                            : ls::ref::Light::Point;
    r.position = {l.position[0], l.position[1], l.position[2]};
    r.direction = glm::normalize(glm::dvec3(l.direction[0], l.direction[1], l.direction[2]));
    r.intensity = {l.intensity[0], l.intensity[1], l.intensity[2]};
    r.outerAngle = glm::radians(static_cast<double>(l.outerConeAngleDegrees));
    r.innerAngle = glm::radians(static_cast<double>(l.innerConeAngleDegrees));
    r.range = l.range >= 1e29f ? std::numeric_limits<double>::infinity() : l.range;
    r.windowedRange = l.rangeFalloff == lightscatter::RangeFalloff::Window;
    r.r0 = l.radius;
    return r;
}

namespace {

// `lin(medium, light, ray)` for every pixel's ray, as RGBA with alpha 0.
template <typename Lin>
std::vector<float> perPixel(const TestFrame& frame, Lin lin) {
    const FrameSpec& s = frame.spec();
    const auto medium = refMedium(s.medium);
    const auto light = refLight(frame.light());
    std::vector<float> want;
    for (uint32_t y = 0; y < s.screen.height; ++y)
        for (uint32_t x = 0; x < s.screen.width; ++x) {
            const PixelRay r = pixelRay(s.scene, s.view, s.screen.width, s.screen.height, x, y,
                                        s.medium.maxDistance);
            const glm::dvec3 v = lin(medium, light, ls::ref::Ray{r.origin, r.dir, r.S});
            want.insert(want.end(), {static_cast<float>(v.x), static_cast<float>(v.y),
                                     static_cast<float>(v.z), 0.0f});
        }
    return want;
}

}  // namespace

std::vector<float> float64Unshadowed(const TestFrame& frame) {
    return perPixel(frame, [](const auto& medium, const auto& light, const ls::ref::Ray& ray) {
        return ls::ref::integrateInscatter(medium, light, ray).value;
    });
}

std::vector<float> float64Simplified(const TestFrame& frame, double a0, double a1) {
    return perPixel(frame,
                    [a0, a1](const auto& medium, const auto& light, const ls::ref::Ray& ray) {
                        return ls::ref::simplifiedClosedForm(medium, light, ray, a0, a1);
                    });
}

}  // namespace plugin_test
