#pragma once
// Vulkan-convention projections (clip y down, depth in [0, 1]) in the four depth conventions the
// plugin accepts, and the light's shadow projection for a scene.
#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.h"

namespace host {

glm::mat4 vulkanPerspective(float fovY, float aspect, float nearP, float farP, bool reversed,
                            bool infinite);
glm::mat4 vulkanOrtho(float halfWidth, float halfHeight, float nearP, float farP);

glm::mat4 cameraView(const CameraDesc& camera);
glm::mat4 cameraProjection(const CameraDesc& camera, float aspect);

// World -> light clip for the shadow map: a spot's frustum around its cone (out to its range, or to
// the scene's far side); for a directional light, a box as deep as the scene's bounds and, across
// the light, as wide as the parts of the scene (`parts`: bounds of each draw; empty: the scene's)
// that the camera sees, so a far-away model outside the view does not spread the map's texels
// over kilometres.
glm::mat4 shadowViewProjection(const LightDesc& light, const Bounds& scene,
                               const std::vector<Bounds>& parts, const CameraDesc& camera,
                               float aspect);

// A point light's cube shadow map: world -> clip of each face in Vulkan's layer order +X, -X, +Y,
// -Y, +Z, -Z, oriented as Vulkan samples a cube (lightscatter.h, Light::cubeFaceViewProjections):
// 90-degree GL-style perspectives (clip y up, depth [0, 1] increasing away from the light) with
// the classic cube cameras' up vectors. The far plane reaches the scene's farthest corner.
std::array<glm::mat4, 6> cubeFaceViewProjections(const LightDesc& light, const Bounds& scene);

}  // namespace host
