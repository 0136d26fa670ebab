#pragma once
// The host's scene description in the plugin's terms.
#include <glm/glm.hpp>

#include <lightscatter/lightscatter.h>
#include "scene/scene.h"

namespace host {

lightscatter::Mat4 toPluginMatrix(const glm::mat4& m);
lightscatter::Camera toPluginCamera(const CameraDesc& camera, const glm::mat4& view,
                                    const glm::mat4& projection);
lightscatter::Light toPluginLight(const LightDesc& light, const glm::mat4& shadowViewProj,
                                  bool shadowed);
lightscatter::Medium toPluginMedium(const MediumDesc& medium);

// The plugin's refusal of a frame built from SCENE.json (lightscatter::InvalidInput), in the
// scene's terms: its file name first and its own field names ("camera.near", not the plugin's
// "camera.nearPlane"). Refusals that are not about the scene keep the plugin's words.
std::string pluginRefusalInSceneTerms(const std::string& message, const std::string& scenePath);

}  // namespace host
