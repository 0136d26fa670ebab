#include "reference_renderer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "camera_math.h"
#include "float64_model/closed_forms.h"
#include "float64_model/inscatter_integral.h"
#include "float64_model/ray_geometry.h"
#include "float64_model/transmittance.h"
#include "visibility.h"

namespace host::reference {

ls::ref::Light toReferenceLight(const LightDesc& l) {
    ls::ref::Light out;
    out.type = l.type == lightscatter::LightType::Directional ? ls::ref::Light::Directional
               : l.type == lightscatter::LightType::Spot      ? ls::ref::Light::Spot
                                                              : ls::ref::Light::Point;
    out.position = glm::dvec3(l.position);
    out.direction = glm::normalize(glm::dvec3(l.direction));
    out.intensity = glm::dvec3(l.intensity);
    out.outerAngle = glm::radians(static_cast<double>(l.outerConeAngleDegrees));
    out.innerAngle = glm::radians(static_cast<double>(l.innerConeAngleDegrees));
    // The host's "no range" (1e30) is the model's infinite one.
    out.range = l.range >= 1e29f ? std::numeric_limits<double>::infinity() : l.range;
    out.windowedRange = l.rangeFalloff == lightscatter::RangeFalloff::Window;
    out.r0 = l.radius;
    return out;
}

ls::ref::Medium toReferenceMedium(const MediumDesc& m) {
    ls::ref::Medium out;
    // The plugin folds a homogeneous density into its float coefficients (exactly so at 1): the
    // reference must model those coefficients, not the product in double.
    const float fold = m.nonUniform() ? 1.0f : m.density;
    out.betaR = glm::dvec3(m.betaR * fold);
    out.betaM = glm::dvec3(m.betaM * fold);
    out.sigmaA = glm::dvec3(m.sigmaA * fold);
    if (m.nonUniform()) {
        out.density.base = m.density;
        if (m.heightFog) out.density.heightFog = {m.heightFog->baseHeight, m.heightFog->falloff};
        for (const lightscatter::FogVolume& v : m.fogVolumes) {
            ls::ref::FogBox box;
            box.center = {v.center[0], v.center[1], v.center[2]};
            box.halfExtents = {v.halfExtents[0], v.halfExtents[1], v.halfExtents[2]};
            for (int j = 0; j < 3; ++j)
                box.axes[j] = glm::normalize(glm::dvec3(v.axes[j][0], v.axes[j][1], v.axes[j][2]));
            box.density = v.density;
            box.fade = v.fade;
            out.density.volumes.push_back(box);
        }
    }
    out.g = m.g;
    out.miePhase = m.phase == lightscatter::MiePhase::Isotropic ? ls::ref::Medium::Isotropic
                   : m.phase == lightscatter::MiePhase::Hazy    ? ls::ref::Medium::Hazy
                                                                : ls::ref::Medium::CornetteShanks;
    out.maxDistance = m.maxDistance;
    return out;
}

ReferenceScene::ReferenceScene(const SceneDesc& scene, const MeshData& mesh, uint32_t width,
                               uint32_t height, const ReferenceOptions& options)
    : camera_(scene.camera, width, height),
      bvh_(Bvh::fromMesh(mesh, options.traversal)),
      medium_(toReferenceMedium(scene.medium)),
      options_(options) {
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    for (std::size_t i = 0; i < scene.lightCount(); ++i) {
        const LightDesc& l = scene.lightAt(i);
        lights_.push_back(toReferenceLight(l));
        Cookie c;
        if (l.cookie) {
            // The matrix the host hands the plugin (a spot's does not depend on the parts).
            c.projection = glm::dmat4(
                shadowViewProjection(l, mesh.bounds, {}, scene.camera, static_cast<float>(aspect)));
            c.width = l.cookie->width;
            c.height = l.cookie->height;
            c.linear.reserve(std::size_t{c.width} * c.height);
            auto decode = [](uint8_t v) {  // the sRGB transfer function, as Vulkan decodes it
                const double x = v / 255.0;
                return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
            };
            for (std::size_t t = 0; t < std::size_t{c.width} * c.height; ++t)
                c.linear.emplace_back(decode(l.cookie->rgba[4 * t]),
                                      decode(l.cookie->rgba[4 * t + 1]),
                                      decode(l.cookie->rgba[4 * t + 2]));
        }
        cookies_.push_back(std::move(c));
    }
}

glm::dvec3 ReferenceScene::Cookie::at(const glm::dvec3& p) const {
    const glm::dvec4 X = projection * glm::dvec4(p, 1.0);
    if (!(X.w > 0.0)) return glm::dvec3(1.0);
    const double u = X.x / X.w * 0.5 + 0.5, v = X.y / X.w * 0.5 + 0.5;
    if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) return glm::dvec3(1.0);
    const double px = u * width - 0.5, py = v * height - 0.5;
    const double fx = std::floor(px), fy = std::floor(py);
    auto texel = [&](double x, double y) {
        const auto cx = static_cast<std::size_t>(std::clamp(x, 0.0, width - 1.0));
        const auto cy = static_cast<std::size_t>(std::clamp(y, 0.0, height - 1.0));
        return linear[cy * width + cx];
    };
    const double ax = px - fx, ay = py - fy;
    return glm::mix(glm::mix(texel(fx, fy), texel(fx + 1, fy), ax),
                    glm::mix(texel(fx, fy + 1), texel(fx + 1, fy + 1), ax), ay);
}

ls::ref::Ray ReferenceScene::pixelRay(uint32_t x, uint32_t y) const {
    return viewRay(camera_.pixelDirection(x, y));
}

ls::ref::Ray ReferenceScene::viewRay(const glm::dvec3& direction) const {
    const ViewRayEnd end = traceViewRay(camera_, bvh_, direction, medium_.maxDistance);
    return {camera_.eye(), direction, end.distance};
}

std::vector<ls::ref::Interval> ReferenceScene::litIntervals(const ls::ref::Ray& ray,
                                                            std::size_t light) const {
    const LitSearch search{options_.visibilitySamples, options_.boundaryRelTol, options_.shadows};
    const ls::ref::Light& l = lights_.at(light);
    return reference::litIntervals(LightVisibility(bvh_, l), l, ray, search);
}

glm::dvec3 ReferenceScene::inscatter(const ls::ref::Ray& ray, std::size_t light) const {
    const std::vector<ls::ref::Interval> lit = litIntervals(ray, light);
    const ls::ref::Light& l = lights_.at(light);
    // Along a directional light's ray P(t) and E are constant, so the closed form is the exact
    // integral; quadrature would only add its tolerance.
    if (l.type == ls::ref::Light::Directional) {
        return ls::ref::directionalClosedForm(medium_, l, ray, lit);
    }
    ls::ref::QuadOptions quad;
    quad.relTol = options_.relTol;
    const Cookie& cookie = cookies_.at(light);
    if (cookie.width == 0) return ls::ref::integrateInscatter(medium_, l, ray, lit, quad).value;
    // The cookie's factor under the model's integrand, with the pieces integrateInscatter takes and
    // cuts where the factor jumps (the image's edges) or has no value (the plane through the
    // light); its texels' kinks are left to the adaptive rule.
    const std::vector<ls::ref::Interval> lit01 = ls::ref::normalizeIntervals(lit, ray.length);
    if (lit01.empty()) return glm::dvec3(0.0);
    std::vector<double> cuts = ls::ref::inscatterBreakpoints(medium_, l, ray, lit01);
    const glm::dvec4 a = cookie.projection * glm::dvec4(ray.origin, 1.0);
    const glm::dvec4 b = cookie.projection * glm::dvec4(ray.direction, 0.0);
    auto crossing = [&](double c0, double c1) {  // where c0 + s c1 = 0
        if (c1 != 0.0) cuts.push_back(-c0 / c1);
    };
    crossing(a.w, b.w);
    for (double ndc : {-1.0, 1.0}) {
        crossing(a.x - ndc * a.w, b.x - ndc * b.w);
        crossing(a.y - ndc * a.w, b.y - ndc * b.w);
    }
    const std::vector<ls::ref::Interval> pieces = ls::ref::splitAt(lit01, std::move(cuts));
    return ls::ref::integrateAdaptive(
               [&](double s) {
                   return ls::ref::inscatterIntegrand(medium_, l, ray, s) *
                          cookie.at(ray.origin + s * ray.direction);
               },
               pieces, quad)
        .value;
}

glm::dvec3 ReferenceScene::inscatter(const ls::ref::Ray& ray) const {
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < lights_.size(); ++i) sum += inscatter(ray, i);
    return sum;
}

glm::dvec3 ReferenceScene::transmittance(const ls::ref::Ray& ray) const {
    return ls::ref::viewTransmittance(medium_, ray);
}

ReferenceImage renderReference(const SceneDesc& scene, const MeshData& mesh, uint32_t width,
                               uint32_t height, const ReferenceOptions& options,
                               std::function<void(double fraction)> progress) {
    ReferenceImage image;
    image.width = width;
    image.height = height;
    const std::size_t pixels = std::size_t{width} * height;
    image.rgb.assign(pixels * 3, 0.0);
    image.distance.assign(pixels, 0.0);
    if (pixels > 0) {
        const ReferenceScene prepared(scene, mesh, width, height, options);
        uint32_t threads = options.threads != 0 ? options.threads
                                                : std::max(std::thread::hardware_concurrency(), 1u);
        threads = std::min(threads, height);

        std::atomic<uint32_t> nextRow{0};
        std::atomic<bool> failed{false};
        std::mutex progressMutex;
        uint32_t rowsDone = 0;
        std::exception_ptr error;
        auto work = [&] {
            try {
                for (uint32_t y = nextRow++; y < height && !failed; y = nextRow++) {
                    for (uint32_t x = 0; x < width; ++x) {
                        const ls::ref::Ray ray = prepared.pixelRay(x, y);
                        const glm::dvec3 lin = prepared.inscatter(ray);
                        const std::size_t i = std::size_t{y} * width + x;
                        image.rgb[3 * i + 0] = lin.r;
                        image.rgb[3 * i + 1] = lin.g;
                        image.rgb[3 * i + 2] = lin.b;
                        image.distance[i] = ray.length;
                    }
                    const std::lock_guard lock(progressMutex);
                    ++rowsDone;
                    if (progress && rowsDone < height)
                        progress(static_cast<double>(rowsDone) / height);
                }
            } catch (...) {
                const std::lock_guard lock(progressMutex);
                if (!error) error = std::current_exception();
                failed = true;
            }
        };
        std::vector<std::thread> pool;
        for (uint32_t t = 1; t < threads; ++t) pool.emplace_back(work);
        work();  // the calling thread is one of the workers
        for (std::thread& t : pool) t.join();
        if (error) std::rethrow_exception(error);
    }
    if (progress) progress(1.0);
    return image;
}

}  // namespace host::reference
