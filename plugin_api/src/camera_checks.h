#pragma once
// The engine's camera, checked against itself (the view a rotation and a translation, the
// projection a Vulkan perspective that agrees with the camera's own fields) and against what its
// depth buffer resolves.
#include <vulkan/vulkan.h>

#include <lightscatter/lightscatter.h>
#include "shared/scattering_params.h"

namespace lightscatter::detail {

// The camera's matrices and the planes the nodes use, read from the projection where the engine
// left them 0.
ls::CameraParams setupCamera(const Camera& c);

// Standard depth, or a UNORM depth buffer either way round, steps by 2^-b (lightscatter.h,
// limits::kDepthStepsPerDistance): the farthest distance it must tell apart (the far plane, or with
// an infinite one the sky distance) may be at most 2^b / 16 times the near plane.
void checkDepthResolution(const ls::CameraParams& camera, float maxDistance, VkFormat format);

// What the view and projection make together: a world -> clip matrix that is not singular, and a
// projection of a scale float32 carries.
void checkViewProjection(const ls::CameraParams& camera);

}  // namespace lightscatter::detail
