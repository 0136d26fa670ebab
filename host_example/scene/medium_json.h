#pragma once
// SCENE.json's "medium" object outside a scene file: read with the scene file's rules (a panel
// script's medium step) and written back (the viewer's report log).
#include <nlohmann/json.hpp>
#include <string>

#include "scene/scene.h"

namespace host {

// `start` with the fields `v` gives replaced, as loadSceneFile reads them; throws SceneError
// naming `source` and the field.
MediumDesc readMediumJson(const nlohmann::json& v, const std::string& source, MediumDesc start);

// Every field of `m` in SCENE.json's terms (heightFog null when there is none).
nlohmann::json mediumJson(const MediumDesc& m);

}  // namespace host
