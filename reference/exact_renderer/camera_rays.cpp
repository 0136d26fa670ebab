#include "camera_rays.h"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "camera_math.h"

namespace host::reference {

PixelCamera::PixelCamera(const CameraDesc& camera, uint32_t width, uint32_t height)
    : near_(camera.nearPlane),
      far_(camera.farPlane),
      infiniteFar_(camera.infiniteFar),
      width_(std::max(width, 1u)),
      height_(std::max(height, 1u)) {
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    view_ = glm::dmat4(cameraView(camera));
    const glm::dmat4 projection(cameraProjection(camera, aspect));
    inverseViewProjection_ = glm::inverse(projection * view_);
    const glm::dmat4 inverseView = glm::inverse(view_);
    eye_ = glm::dvec3(inverseView[3]);
    axis_ = -glm::normalize(glm::dvec3(inverseView[2]));
}

glm::dvec3 PixelCamera::directionAtNdc(double x, double y) const {
    const glm::dvec4 p = inverseViewProjection_ * glm::dvec4(x, y, 0.5, 1.0);
    return glm::normalize(glm::dvec3(p) / p.w - eye_);
}

glm::dvec3 PixelCamera::pixelDirection(uint32_t x, uint32_t y) const {
    return directionAtNdc((x + 0.5) / width_ * 2.0 - 1.0, (y + 0.5) / height_ * 2.0 - 1.0);
}

double PixelCamera::cameraZ(const glm::dvec3& p) const {
    return -(view_ * glm::dvec4(p, 1.0)).z;
}

std::pair<double, double> PixelCamera::clipRange(const glm::dvec3& direction) const {
    // camZ is affine along the ray: camZ(eye) + t * rate.
    const double rate = -(view_ * glm::dvec4(direction, 0.0)).z;
    if (!(rate > 0.0)) return {1.0, 0.0};
    const double atEye = cameraZ(eye_);
    const double tNear = std::max((near_ - atEye) / rate, 0.0);
    const double tFar =
        infiniteFar_ ? std::numeric_limits<double>::infinity() : (far_ - atEye) / rate;
    return {tNear, tFar};
}

double PixelCamera::skyDistance(const glm::dvec3& direction, double maxDistance) const {
    if (infiniteFar_) return maxDistance;
    const double c = std::max(glm::dot(direction, axis_), 1e-4);
    return std::min(far_ / c, maxDistance);
}

ViewRayEnd traceViewRay(const PixelCamera& camera, const Bvh& bvh, const glm::dvec3& direction,
                        double maxDistance) {
    const auto [tNear, tFar] = camera.clipRange(direction);
    if (tNear <= tFar) {
        if (const auto hit = bvh.closestHit(PreparedRay(camera.eye(), direction), tNear, tFar)) {
            return {hit->t, false};
        }
    }
    return {camera.skyDistance(direction, maxDistance), true};
}

}  // namespace host::reference
