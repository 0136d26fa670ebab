#pragma once
// Whether a light, or one face of a point light's cube, can reach a view ray: the tests that keep
// a light whose volume misses the view from adding any node.
#include <vulkan/vulkan.h>

#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "scattering_params.h"

namespace ls {

// Whether any light can scatter towards the camera (conservative): false when nothing is emitted,
// nothing scatters, or a spot's cone (within its range, or within the reach of the view) misses
// the view frustum.
bool lightTouchesView(const CameraParams& camera, const LightParams& light,
                      const MediumParams& medium);
// Whether cube face `face` (+X, -X, +Y, -Y, +Z, -Z) of a point light reaches a view ray: its
// square pyramid against the view frustum, each bounded by how far the view reaches (conservative:
// true when unsure).
bool cubeFaceTouchesView(const CameraParams& camera, const LightParams& light,
                         const MediumParams& medium, int face);

// The pixels of a `screen` whose view rays may cross the light's volume (a point light's range, a
// spot's cone within its range, each within the view's reach): conservative, the whole screen
// when unsure (a directional light, an unbounded volume, the camera in or beside the volume).
// The corners of a convex solid holding the light's volume within the view's reach, projected
// (NDC): a point light's cube around its sphere, or a spot's apex (first) and an octagon around
// its cone's circle. None where unsure (a directional light, an unbounded volume, a corner behind
// the camera's near plane). clipToNear: a spot's pyramid is cut by that plane instead where its
// apex lies in front (its corners then also where its edges cross the plane).
std::optional<std::vector<glm::vec2>> lightScreenCorners(const CameraParams& camera,
                                                         const LightParams& light,
                                                         const MediumParams& medium,
                                                         bool clipToNear);

VkRect2D lightScreenRect(const CameraParams& camera, const LightParams& light,
                         const MediumParams& medium, VkExtent2D screen);

}  // namespace ls
