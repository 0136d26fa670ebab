#include "model_conversion.h"

#include "float64_model/closed_forms.h"
#include "float64_model/inscatter_integral.h"
#include "float64_model/ray_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <glm/common.hpp>
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

namespace {

// The cookie as the GPU samples it: bilinear between texel centres, clamped to the edge texels.
struct Cookie {
    const std::vector<float>& rgba;
    int size;
    glm::dvec3 texel(int x, int y) const {
        x = std::clamp(x, 0, size - 1);
        y = std::clamp(y, 0, size - 1);
        const float* t = &rgba[(static_cast<size_t>(y) * size + x) * 4];
        return {t[0], t[1], t[2]};
    }
    glm::dvec3 at(double u, double v) const {
        if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) return glm::dvec3(1.0);
        const double px = u * size - 0.5, py = v * size - 0.5;
        const double fx = std::floor(px), fy = std::floor(py);
        const int x = static_cast<int>(fx), y = static_cast<int>(fy);
        const double ax = px - fx, ay = py - fy;
        return glm::mix(glm::mix(texel(x, y), texel(x + 1, y), ax),
                        glm::mix(texel(x, y + 1), texel(x + 1, y + 1), ax), ay);
    }
};

}  // namespace

std::vector<float> float64WithCookie(const TestFrame& frame) {
    const std::vector<float>& rgba = frame.spec().cookie;
    const Cookie cookie{
        rgba, static_cast<int>(std::lround(std::sqrt(static_cast<double>(rgba.size()) / 4.0)))};
    glm::dmat4 M(1.0);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) M[c][r] = frame.light().shadowViewProjection[c * 4 + r];
    return perPixel(frame, [&](const auto& medium, const auto& light, const ls::ref::Ray& ray) {
        const std::optional<ls::ref::Ray> unit = ls::ref::unitRay(ray);
        if (!unit) return glm::dvec3(0.0);
        const glm::dvec4 a = M * glm::dvec4(unit->origin, 1.0),
                         b = M * glm::dvec4(unit->direction, 0.0);
        // The pieces end where the cookie's bilinear value has a kink (its texel-centre lines), a
        // jump (the image's edges) or is undefined (the plane through the light, w = 0), and where
        // the light's own integrand changes character.
        std::vector<double> cuts = ls::ref::lightFeatureDistances(light, *unit);
        auto crossing = [&](double num0, double num1) {  // where num0 + s num1 = 0
            if (num1 != 0.0) cuts.push_back(-num0 / num1);
        };
        crossing(a.w, b.w);
        for (int i = 0; i <= cookie.size; ++i) {
            for (double uv : {static_cast<double>(i) / cookie.size, (i + 0.5) / cookie.size}) {
                const double ndc = 2.0 * uv - 1.0;  // x / w = ndc
                crossing(a.x - ndc * a.w, b.x - ndc * b.w);
                crossing(a.y - ndc * a.w, b.y - ndc * b.w);
            }
        }
        const std::vector<ls::ref::Interval> lit = ls::ref::spotLitIntervals(light, *unit);
        const std::vector<ls::ref::Interval> pieces = ls::ref::splitAt(lit, std::move(cuts));
        ls::ref::QuadOptions options;
        options.relTol = 1e-8;
        return ls::ref::integrateAdaptive(
                   [&](double s) {
                       const glm::dvec4 X = a + s * b;
                       const glm::dvec3 color =
                           X.w > 0.0 ? cookie.at(X.x / X.w * 0.5 + 0.5, X.y / X.w * 0.5 + 0.5)
                                     : glm::dvec3(1.0);
                       return ls::ref::inscatterIntegrand(medium, light, *unit, s) * color;
                   },
                   pieces, options)
            .value;
    });
}

std::vector<float> float64Simplified(const TestFrame& frame, double a0, double a1) {
    return perPixel(frame,
                    [a0, a1](const auto& medium, const auto& light, const ls::ref::Ray& ray) {
                        return ls::ref::simplifiedClosedForm(medium, light, ray, a0, a1);
                    });
}

}  // namespace plugin_test
