#pragma once
// A point light's cube shadow map: each face's matrix checked against the face Vulkan samples
// there.
#include <glm/glm.hpp>
#include <string>

#include <lightscatter/lightscatter.h>

namespace lightscatter::detail {

// Checks face `i`'s world -> clip matrix (`at`.cubeFaceViewProjections[i]) against the face it
// must be: its axis, its corners (a 90-degree square frustum with Vulkan's orientation) and its
// depth direction, at 1 m and 10 m from the light, to 1e-3 in clip x/w and y/w.
glm::mat4 checkCubeFace(const Mat4& given, size_t i, const glm::vec3& light, bool reversedZ,
                        const std::string& at);

}  // namespace lightscatter::detail
