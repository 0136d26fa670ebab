#include "reference_renderer.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "float64_model/closed_forms.h"
#include "float64_model/inscatter_integral.h"
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
    out.betaR = glm::dvec3(m.betaR);
    out.betaM = glm::dvec3(m.betaM);
    out.sigmaA = glm::dvec3(m.sigmaA);
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
      bvh_(Bvh::fromMesh(mesh)),
      medium_(toReferenceMedium(scene.medium)),
      options_(options) {
    for (std::size_t i = 0; i < scene.lightCount(); ++i)
        lights_.push_back(toReferenceLight(scene.lightAt(i)));
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
    return ls::ref::integrateInscatter(medium_, l, ray, lit, quad).value;
}

glm::dvec3 ReferenceScene::inscatter(const ls::ref::Ray& ray) const {
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < lights_.size(); ++i) sum += inscatter(ray, i);
    return sum;
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
