#pragma once
// Vulkan-convention projections (clip y down, depth in [0, 1]) in the four depth conventions the
// plugin accepts, and the light's shadow projection for a scene.
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace host {

glm::mat4 vulkanPerspective(float fovY, float aspect, float nearP, float farP, bool reversed,
                            bool infinite);
glm::mat4 vulkanOrtho(float halfWidth, float halfHeight, float nearP, float farP);

glm::mat4 cameraView(const CameraDesc& camera);
glm::mat4 cameraProjection(const CameraDesc& camera, float aspect);

// World -> light clip for the shadow map: a spot's frustum around its cone (out to its range, or to
// the scene's far side), a directional light's box around the scene's bounds.
glm::mat4 shadowViewProjection(const LightDesc& light, const Bounds& scene);

}  // namespace host
