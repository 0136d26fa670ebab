#pragma once
// The GPU path's pixel rays in float64, and where each one ends (docs/model.md, "Conventions at the
// edges"): the reference must look along exactly the rays the rasterizer and the plugin's shaders
// look along, or its error would be blamed on the methods.
#include <cstdint>
#include <utility>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "bvh.h"
#include "scene/scene.h"

namespace host::reference {

class PixelCamera {
  public:
    // The engine's own float matrices (cameraView, and cameraProjection with aspect = width /
    // height), promoted to double and inverted in double: the rasterizer renders those float
    // matrices, so their rounding is part of the camera, not an error to correct.
    PixelCamera(const CameraDesc& camera, uint32_t width, uint32_t height);

    // The centre of projection, inverse(view) * (0, 0, 0, 1) (the shader's cameraPos).
    [[nodiscard]] const glm::dvec3& eye() const { return eye_; }
    // Unit view axis, -normalize(inverse(view)[2]) (the shader's cameraForward).
    [[nodiscard]] const glm::dvec3& axis() const { return axis_; }
    [[nodiscard]] uint32_t width() const { return width_; }
    [[nodiscard]] uint32_t height() const { return height_; }

    // Unit direction through a point of Vulkan NDC (x right, y down), as the shader's
    // rayDirection(): the point at depth 0.5 unprojected by inverse(proj * view), minus the eye.
    [[nodiscard]] glm::dvec3 directionAtNdc(double x, double y) const;
    // Through the centre (x + 0.5, y + 0.5) of pixel (x, y); row 0 is the top of the image.
    [[nodiscard]] glm::dvec3 pixelDirection(uint32_t x, uint32_t y) const;

    // Camera-space z of a world point (positive in front), from the view matrix as the
    // rasterizer computes it.
    [[nodiscard]] double cameraZ(const glm::dvec3& p) const;
    // The distances t along eye + t * direction whose camera-space z lies in [near, far] (far is
    // infinite with an infinite far plane): what the rasterizer keeps of that ray. Empty (first >
    // second) for a direction that does not point in front of the camera.
    [[nodiscard]] std::pair<double, double> clipRange(const glm::dvec3& direction) const;
    // S of a sky pixel along a unit direction: min(far / cos, maxDistance), with cos the cosine to
    // the view axis floored at 1e-4 as the shader floors it; maxDistance with an infinite far
    // plane.
    [[nodiscard]] double skyDistance(const glm::dvec3& direction, double maxDistance) const;

  private:
    glm::dmat4 view_{1.0};
    glm::dmat4 inverseViewProjection_{1.0};
    glm::dvec3 eye_{0.0};
    glm::dvec3 axis_{0.0, 0.0, -1.0};
    double near_ = 0.1, far_ = 1000.0;
    bool infiniteFar_ = false;
    uint32_t width_ = 1, height_ = 1;
};

struct ViewRayEnd {
    double distance = 0.0;  // S
    bool sky = false;
};

// Where the ray from the eye along the unit direction ends: the nearest surface the rasterizer
// would keep (camera-space z in [near, far]), or the sky. A surface beyond the far plane is
// clipped and so is sky; one nearer than the near plane is clipped too and the ray sees past it.
// A surface's distance is never capped by maxDistance; only the sky's is.
[[nodiscard]] ViewRayEnd traceViewRay(const PixelCamera& camera, const Bvh& bvh,
                                      const glm::dvec3& direction, double maxDistance);

}  // namespace host::reference
