#pragma once
// The host's scene description in the plugin's terms.
#include <glm/glm.hpp>

#include "lightscatter.h"
#include "scene/scene.h"

namespace host {

lightscatter::Mat4 toPluginMatrix(const glm::mat4& m);
lightscatter::Camera toPluginCamera(const CameraDesc& camera, const glm::mat4& view, const glm::mat4& projection);
lightscatter::Light toPluginLight(const LightDesc& light, const glm::mat4& shadowViewProj, bool shadowed);
lightscatter::Medium toPluginMedium(const MediumDesc& medium);

}  // namespace host
