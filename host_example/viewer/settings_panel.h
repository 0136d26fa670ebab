#pragma once
// The viewer's settings panel: the method and profile, every field of lightscatter::Settings (the
// list of settings_fields.h), each light and the medium, the frame's report (auto's choice and
// why), the GPU time of each pass as bars and the device memory in use, and "save settings".
// Every edit goes through the functions below, which the widgets and a panel script
// (--panel-script) call alike; what the plugin refuses is shown in its own words and the last frame
// it accepted keeps running (the viewer reverts the edit).
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "engine_renderer.h"
#include "scene/scene.h"
#include "settings_fields.h"

namespace host {

// What the panel shows beside what it edits.
struct PanelStatus {
    const lightscatter::FrameReport* report = nullptr;  // the last finished frame's, if any
    bool cpuDevice = false;                             // lavapipe: timings are CPU figures
    uint64_t deviceBytes = 0;                           // the runtime's counter
    std::string note;                                   // the viewer's word (a method's limits)
};

// Throws when `path` holds something other than a settings file: a save replaces only its own kind,
// so that a mistyped name does not lose a scene the output checks do not know of, or a user's
// notes.
void checkSettingsSaveTarget(const std::string& path);

class SettingsPanel {
  public:
    explicit SettingsPanel(const std::string& saveName = "lightscatter-settings.json");

    // The edits. A profile-sized field (SettingField::profileSized) edited under a profile other
    // than custom switches to custom, starting from that profile's sizes, so the edit is what runs.
    void setMethod(RenderOptions& o, lightscatter::Method m) const;
    void setProfile(RenderOptions& o, lightscatter::Profile p) const;
    void setField(RenderOptions& o, const SettingField& f, double value, int component = 0) const;
    // A light's type or shadow-map size changes the engine's targets: rebuildTargets() says so
    // once.
    void setLightType(SceneDesc& s, size_t light, lightscatter::LightType type);
    void setShadowMapSize(SceneDesc& s, size_t light, uint32_t size);
    // The medium as a whole (its density, height fog and fog volumes are edited live: the plugin
    // takes a new medium every frame, and refuses one it cannot render).
    void setMedium(SceneDesc& s, const MediumDesc& medium) const;
    bool rebuildTargets();

    // The settings a frame with these options runs with: the profile's sizes over `custom`.
    static lightscatter::Settings effective(const RenderOptions& o);
    // Writes them to `path` as a --settings file (every field), through a temporary beside it that
    // becomes the file only when whole; returns the line to show. Throws, writing nothing, when
    // the check given to setSaveCheck refuses the path or the write fails.
    std::string save(const RenderOptions& o, const std::string& path) const;
    // The rules every output of the command follows (output_set.h): a save must not replace the
    // scene, a file it reads, the settings file or another output. Throws naming the rule.
    void setSaveCheck(std::function<void(const std::string&)> check) {
        saveCheck_ = std::move(check);
    }

    // The plugin refused the last edit (its message), or accepted the frame.
    void refused(const std::string& message) { message_ = message; }
    const std::string& message() const { return message_; }

    // Draws the panel (inside an ImGui frame); edits `o` and `scene` through the functions above.
    void draw(RenderOptions& o, SceneDesc& scene, const PanelStatus& status);

    // Where the panel stands on a window of width x height pixels. On a window under
    // kRoomWidth x kRoomHeight it is collapsed to its title bar (the picture comes first there; a
    // click on the title opens it), and it is never wider than half the window nor taller than the
    // window less its margins. draw() collapses or opens it when the window crosses that size, and
    // leaves it as the user set it in between.
    static constexpr float kRoomWidth = 800.0f, kRoomHeight = 450.0f;
    struct Layout {
        bool collapsed = false;
        float maxWidth = 0.0f, maxHeight = 0.0f;
    };
    static Layout layout(float width, float height);

  private:
    void drawSettings(RenderOptions& o);
    void drawField(RenderOptions& o, const lightscatter::Settings& shown, const SettingField& f);
    void drawLights(SceneDesc& scene);
    void drawMedium(SceneDesc& scene);
    void drawTimings(const PanelStatus& status) const;

    bool rebuild_ = false;
    int collapsedFor_ = -1;             // the layout's `collapsed` last applied (-1: none yet)
    std::string message_;               // the plugin's refusal, shown until the next accepted edit
    std::array<char, 512> savePath_{};  // the "file" field
    std::string saved_;                 // the line "save settings" gave
    std::function<void(const std::string&)> saveCheck_;
};

}  // namespace host
