#pragma once
// --panel-script FILE.json: edits for the settings panel, one step per frame, made through the
// panel's own functions (what a user's clicks do), so that a test can drive the panel without a
// pointer. FILE.json is an array; step k is made before frame k:
//   {"settings": {"slices": 256, ...}, "method": "auto", "profile": "custom", "save": "out.json",
//    "medium": {"density": 0.5, "heightFog": {...} or null, "fogVolumes": [...]}}
// with the settings in a settings file's terms (settings_fields.h) and the medium in SCENE.json's
// (the fields it gives replace the scene's; "fogVolumes" replaces the whole list).
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "settings_panel.h"

namespace host {

class PanelScript {
  public:
    PanelScript() = default;
    // Reads and checks every step: unknown fields, methods or profiles, or values of the wrong
    // kind, throw one line naming the file, the step and the field.
    explicit PanelScript(const std::string& path);
    size_t size() const { return steps_.size(); }
    // The steps that save, and the file each names: the viewer checks them before the first frame.
    std::vector<std::pair<size_t, std::string>> saves() const;
    // Makes step k (if there is one) through `panel`.
    void apply(size_t k, SettingsPanel& panel, RenderOptions& o, SceneDesc& scene) const;

  private:
    std::string path_;
    std::vector<nlohmann::json> steps_;
};

}  // namespace host
