#include "settings_panel.h"

#include <imgui.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>

#include "image_io.h"
#include "options_as_run.h"
#include "settings_file.h"

namespace host {
namespace {

using lightscatter::LightType;
using lightscatter::Method;
using lightscatter::Profile;

// Auto, then every method (methodInfo()).
std::vector<Method> panelMethods() {
    std::vector<Method> m{Method::Auto};
    for (const lightscatter::MethodInfo& info : lightscatter::methodInfo())
        m.push_back(info.method);
    return m;
}
constexpr std::array kProfiles{Profile::HighQuality,     Profile::Balanced,
                               Profile::HighPerformance, Profile::LowHighQuality,
                               Profile::LowBalanced,     Profile::LowHighPerformance,
                               Profile::Custom};
constexpr std::array kLightTypes{"directional", "spot", "point"};
constexpr std::array kPhases{"cornette-shanks", "isotropic", "hazy"};
constexpr std::array<uint32_t, 7> kShadowSizes{0, 256, 512, 1024, 2048, 4096, 8192};

int lightTypeIndex(LightType t) {
    return t == LightType::Directional ? 0 : t == LightType::Spot ? 1 : 2;
}
LightType lightTypeAt(int i) {
    return i == 0 ? LightType::Directional : i == 1 ? LightType::Spot : LightType::Point;
}
int phaseIndex(lightscatter::MiePhase p) {
    return p == lightscatter::MiePhase::CornetteShanks ? 0
           : p == lightscatter::MiePhase::Isotropic    ? 1
                                                       : 2;
}
lightscatter::MiePhase phaseAt(int i) {
    return i == 0   ? lightscatter::MiePhase::CornetteShanks
           : i == 1 ? lightscatter::MiePhase::Isotropic
                    : lightscatter::MiePhase::Hazy;
}

// A colour in 1/m or W: three components dragged over decades.
bool dragVec3(const char* label, glm::vec3& v, float lo, float hi, const char* format) {
    float a[3] = {v.x, v.y, v.z};
    const bool changed = ImGui::DragFloat3(label, a, std::max(1e-7f, (v.x + v.y + v.z) * 0.005f),
                                           lo, hi, format, ImGuiSliderFlags_AlwaysClamp);
    if (changed) v = {a[0], a[1], a[2]};
    return changed;
}

}  // namespace

SettingsPanel::SettingsPanel(const std::string& saveName) {
    std::snprintf(savePath_.data(), savePath_.size(), "%s", saveName.c_str());
}

void SettingsPanel::setMethod(RenderOptions& o, Method m) const {
    o.method = m;
}

void SettingsPanel::setProfile(RenderOptions& o, Profile p) const {
    o.profile = p;
}

void SettingsPanel::setField(RenderOptions& o, const SettingField& f, double value,
                             int component) const {
    if (f.profileSized && o.profile != Profile::Custom) {
        o.custom = effective(o);
        o.profile = Profile::Custom;
    }
    setFieldValue(o.custom, f, value, component);
}

void SettingsPanel::setLightType(SceneDesc& s, size_t light, LightType type) {
    LightDesc& l = s.lightAt(light);
    if (l.type == type) return;
    l.type = type;
    rebuild_ = true;
}

void SettingsPanel::setShadowMapSize(SceneDesc& s, size_t light, uint32_t size) {
    LightDesc& l = s.lightAt(light);
    if (l.shadowMapSize == size) return;
    l.shadowMapSize = size;
    rebuild_ = true;
}

bool SettingsPanel::rebuildTargets() {
    return std::exchange(rebuild_, false);
}

lightscatter::Settings SettingsPanel::effective(const RenderOptions& o) {
    return lightscatter::profileSettings(o.profile, o.custom);
}

void checkSettingsSaveTarget(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return;  // absent, or refused by the write
    // A file the settings reader takes, in either of its forms (nested by method, or flat).
    bool settings = true;
    try {
        loadSettingsFile(path, lightscatter::Settings{});
    } catch (const std::exception&) {
        settings = false;
    }
    if (!settings)
        throw std::runtime_error("save settings " + path +
                                 ": exists and is not a settings file; saving would replace it "
                                 "(give another name)");
}

std::string SettingsPanel::save(const RenderOptions& o, const std::string& path) const {
    if (saveCheck_) saveCheck_(path);
    checkSettingsSaveTarget(path);
    // What ran, so that the command below reads it back; and never settings the plugin refuses
    // (a script's step may save an edit before the frame that would refuse it).
    const lightscatter::Settings saved = effective(asRun(o));
    try {
        lightscatter::checkSettings(saved);
    } catch (const lightscatter::InvalidInput& e) {
        return "not saved: " + std::string(e.what());
    }
    writeTextFile(path, settingsFileText(saved), "save settings");
    return "wrote " + path + ": lightscatter view SCENE --method " +
           lightscatter::methodName(o.method) + " --profile custom --settings " + path;
}

SettingsPanel::Layout SettingsPanel::layout(float width, float height) {
    constexpr float kMargin = 8.0f;
    Layout l;
    l.collapsed = width < kRoomWidth || height < kRoomHeight;
    l.maxWidth = std::max(1.0f, 0.5f * width);
    l.maxHeight = std::max(1.0f, height - 2.0f * kMargin);
    return l;
}

void SettingsPanel::draw(RenderOptions& o, SceneDesc& scene, const PanelStatus& status) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const Layout l = layout(display.x, display.y);
    // Collapsed or opened when the window crosses the size (and on the first frame), not every
    // frame: between two crossings the user's click decides.
    if (collapsedFor_ != static_cast<int>(l.collapsed)) {
        ImGui::SetNextWindowCollapsed(l.collapsed, ImGuiCond_Always);
        collapsedFor_ = static_cast<int>(l.collapsed);
    }
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(std::min(480.0f, l.maxWidth), std::min(560.0f, l.maxHeight)),
                             ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(160.0f, l.maxWidth), 0.0f),
                                        ImVec2(l.maxWidth, l.maxHeight));
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (!ImGui::Begin("lightscatter (F1 hides)")) {
        ImGui::End();
        return;
    }
    if (ImGui::BeginCombo("method", lightscatter::methodName(o.method))) {
        for (Method m : panelMethods())
            if (ImGui::Selectable(lightscatter::methodName(m), m == o.method)) setMethod(o, m);
        ImGui::EndCombo();
    }
    if (ImGui::BeginCombo("profile", lightscatter::profileName(o.profile))) {
        for (Profile p : kProfiles)
            if (ImGui::Selectable(lightscatter::profileName(p), p == o.profile)) setProfile(o, p);
        ImGui::EndCombo();
    }
    if (status.report && status.report->frame) {
        ImGui::TextWrapped("ran: %s", status.report->method.c_str());
        ImGui::TextWrapped("why: %s", status.report->reason.c_str());
        if (!status.report->notice.empty())
            ImGui::TextWrapped("notice: %s", status.report->notice.c_str());
    }
    if (!status.note.empty()) ImGui::TextWrapped("%s", status.note.c_str());
    if (!message_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("refused: %s", message_.c_str());
        ImGui::PopStyleColor();
    }
    drawTimings(status);
    if (ImGui::CollapsingHeader("Settings", ImGuiTreeNodeFlags_DefaultOpen)) drawSettings(o);
    if (ImGui::CollapsingHeader("Lights")) drawLights(scene);
    if (ImGui::CollapsingHeader("Medium")) drawMedium(scene);
    ImGui::End();
}

void SettingsPanel::drawTimings(const PanelStatus& status) const {
    ImGui::Text("device memory in use: %.1f MiB",
                static_cast<double>(status.deviceBytes) / (1024.0 * 1024.0));
    const lightscatter::FrameReport* r = status.report;
    if (!r || !r->timed) return;
    ImGui::TextWrapped("plugin: %.2f ms on the GPU%s", r->totalMilliseconds,
                       status.cpuDevice ? " (a CPU device: CPU timings)" : "");
    // One bar per pass in execution order, as long as its share of the slowest pass; a scrolling
    // box of its own, so that epipolar's dozens of passes leave room for the settings.
    double longest = 0.0;
    for (const auto& p : r->passes) longest = std::max(longest, p.milliseconds);
    ImGui::BeginChild("passes", ImVec2(0.0f, 150.0f), true);
    for (const auto& p : r->passes) {
        char label[160];
        std::snprintf(label, sizeof label, "%s %.2f ms", p.name.c_str(), p.milliseconds);
        ImGui::ProgressBar(longest > 0 ? static_cast<float>(p.milliseconds / longest) : 0.0f,
                           ImVec2(-1.0f, 0.0f), label);
    }
    ImGui::EndChild();
}

void SettingsPanel::drawField(RenderOptions& o, const lightscatter::Settings& shown,
                              const SettingField& f) {
    ImGui::PushID(f.name.c_str());
    const double v = fieldValue(shown, f);
    const std::string label = fieldKey(f);
    const float lo = static_cast<float>(f.sliderMin), hi = static_cast<float>(f.sliderMax);
    switch (f.kind) {
        case SettingField::Kind::Whole: {
            int i = static_cast<int>(std::min(v, 2147483647.0));
            if (ImGui::SliderInt(
                    label.c_str(), &i, static_cast<int>(f.sliderMin), static_cast<int>(f.sliderMax),
                    "%d", f.sliderMax > 64 ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None))
                setField(o, f, i);
            break;
        }
        case SettingField::Kind::Number: {
            float x = static_cast<float>(v);
            const ImGuiSliderFlags flags =
                f.logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
            if (ImGui::SliderFloat(label.c_str(), &x, lo, hi, "%.4g", flags)) setField(o, f, x);
            break;
        }
        case SettingField::Kind::Boolean: {
            bool b = v != 0.0;
            if (ImGui::Checkbox(label.c_str(), &b)) setField(o, f, b ? 1.0 : 0.0);
            break;
        }
        case SettingField::Kind::Choice: {
            const int c = static_cast<int>(v);
            const size_t n = f.choices.size();
            if (ImGui::BeginCombo(label.c_str(),
                                  c >= 0 && size_t(c) < n ? f.choices[size_t(c)].c_str() : "?")) {
                for (size_t k = 0; k < n; ++k)
                    if (ImGui::Selectable(f.choices[k].c_str(), int(k) == c))
                        setField(o, f, double(k));
                ImGui::EndCombo();
            }
            break;
        }
        case SettingField::Kind::Vector4: {
            float a[4];
            for (int c = 0; c < 4; ++c) a[c] = static_cast<float>(fieldValue(shown, f, c));
            if (ImGui::SliderFloat4(label.c_str(), a, lo, hi, "%.3f"))
                for (int c = 0; c < 4; ++c) setField(o, f, a[c], c);
            break;
        }
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s%s", f.doc.c_str(),
                          f.profileSized ? " (the profile's; editing it selects custom)" : "");
    ImGui::PopID();
}

// Settings' own fields, then each method's under its name (methodInfo()).
void SettingsPanel::drawSettings(RenderOptions& o) {
    const lightscatter::Settings shown = effective(o);
    for (const SettingField& f : settingFields())
        if (fieldGroup(f).empty()) drawField(o, shown, f);
    for (const lightscatter::MethodInfo& m : lightscatter::methodInfo()) {
        if (m.settings.empty() || !ImGui::TreeNode(m.name.c_str())) continue;
        for (const SettingField& own : m.settings) drawField(o, shown, *findSettingField(own.name));
        ImGui::TreePop();
    }
    ImGui::InputText("file", savePath_.data(), savePath_.size());
    if (ImGui::Button("save settings")) {
        try {
            saved_ = save(o, savePath_.data());
        } catch (const std::runtime_error& e) {
            saved_ = e.what();  // refused or failed: nothing was written
        }
    }
    if (!saved_.empty()) ImGui::TextWrapped("%s", saved_.c_str());
}

void SettingsPanel::drawLights(SceneDesc& scene) {
    for (size_t i = 0; i < scene.lightCount(); ++i) {
        LightDesc& l = scene.lightAt(i);
        ImGui::PushID(static_cast<int>(i));
        ImGui::Text("light %zu", i);
        int type = lightTypeIndex(l.type);
        if (ImGui::Combo("type", &type, kLightTypes.data(), int(kLightTypes.size())))
            setLightType(scene, i, lightTypeAt(type));
        if (l.type != LightType::Directional)
            ImGui::DragFloat3("position", &l.position.x, 0.05f, -1e4f, 1e4f, "%.2f");
        if (l.type != LightType::Point) {
            glm::vec3 d = l.direction;
            if (ImGui::DragFloat3("direction", &d.x, 0.01f, -1.0f, 1.0f, "%.3f") &&
                glm::length(d) > 1e-3f)
                l.direction = glm::normalize(d);
        }
        dragVec3("intensity", l.intensity, 0.0f, lightscatter::limits::kMaxIntensity, "%.4g");
        if (l.type == LightType::Spot) {
            ImGui::SliderFloat("inner cone", &l.innerConeAngleDegrees, 0.1f, 89.0f, "%.1f deg");
            ImGui::SliderFloat("outer cone", &l.outerConeAngleDegrees, 0.1f, 89.0f, "%.1f deg");
        }
        if (l.type != LightType::Directional)
            ImGui::DragFloat("range", &l.range, 0.1f, 0.01f, 1e30f, "%.4g",
                             ImGuiSliderFlags_Logarithmic);
        int sm =
            static_cast<int>(std::find(kShadowSizes.begin(), kShadowSizes.end(), l.shadowMapSize) -
                             kShadowSizes.begin());
        const std::string current = std::to_string(l.shadowMapSize);
        if (ImGui::BeginCombo("shadow map", l.shadowMapSize ? current.c_str() : "none")) {
            for (size_t k = 0; k < kShadowSizes.size(); ++k) {
                const std::string name = kShadowSizes[k] ? std::to_string(kShadowSizes[k]) : "none";
                if (ImGui::Selectable(name.c_str(), int(k) == sm))
                    setShadowMapSize(scene, i, kShadowSizes[k]);
            }
            ImGui::EndCombo();
        }
        ImGui::Separator();
        ImGui::PopID();
    }
}

void SettingsPanel::setMedium(SceneDesc& s, const MediumDesc& medium) const {
    s.medium = medium;
}

namespace {

// A fog volume's box turned about world +Y by `degrees` (its axes; the panel's one rotation).
void setYaw(lightscatter::FogVolume& v, float degrees) {
    const float a = glm::radians(degrees), c = std::cos(a), s = std::sin(a);
    v.axes = {{{c, 0.0f, -s}, {0.0f, 1.0f, 0.0f}, {s, 0.0f, c}}};
}

float yawOf(const lightscatter::FogVolume& v) {
    return glm::degrees(std::atan2(-v.axes[0][2], v.axes[0][0]));
}

// docs/model.md's non-uniform medium: d0, the height fog and each fog volume, on a copy that
// goes through setMedium when a widget changed it.
bool drawFog(MediumDesc& m) {
    bool changed = false;
    changed |= ImGui::DragFloat("density", &m.density, 0.01f, 0.0f,
                                lightscatter::limits::kMaxDensity, "%.3f");
    bool fog = m.heightFog.has_value();
    if (ImGui::Checkbox("height fog", &fog)) {
        changed = true;
        if (fog)
            m.heightFog = lightscatter::HeightFog{0.0f, 0.1f};
        else
            m.heightFog.reset();
    }
    if (m.heightFog) {
        changed |= ImGui::DragFloat("base height (m)", &m.heightFog->baseHeight, 0.05f,
                                    -lightscatter::limits::kMaxLength,
                                    lightscatter::limits::kMaxLength, "%.3f");
        changed |= ImGui::DragFloat("falloff (1/m)", &m.heightFog->falloff, 0.01f, 0.0f,
                                    lightscatter::limits::kMaxFogFalloff, "%.4g",
                                    ImGuiSliderFlags_Logarithmic);
    }
    for (size_t i = 0; i < m.fogVolumes.size(); ++i) {
        lightscatter::FogVolume& v = m.fogVolumes[i];
        ImGui::PushID(static_cast<int>(i));
        ImGui::Text("fog volume %zu", i);
        changed |= ImGui::DragFloat3("center", v.center.data(), 0.05f);
        changed |= ImGui::DragFloat3("half extents", v.halfExtents.data(), 0.02f, 0.0f,
                                     lightscatter::limits::kMaxLength);
        float yaw = yawOf(v);
        if (ImGui::SliderFloat("yaw", &yaw, -180.0f, 180.0f, "%.1f deg")) {
            setYaw(v, yaw);
            changed = true;
        }
        changed |= ImGui::DragFloat("volume density", &v.density, 0.01f, 0.0f,
                                    lightscatter::limits::kMaxDensity, "%.3f");
        changed |= ImGui::DragFloat("fade (m)", &v.fade, 0.01f, 0.0f,
                                    lightscatter::limits::kMaxLength, "%.3f");
        const bool remove = ImGui::Button("remove volume");
        ImGui::PopID();
        if (remove) {
            m.fogVolumes.erase(m.fogVolumes.begin() + static_cast<std::ptrdiff_t>(i));
            return true;
        }
    }
    if (m.fogVolumes.size() < lightscatter::limits::kMaxFogVolumes &&
        ImGui::Button("add fog volume")) {
        m.fogVolumes.emplace_back();
        changed = true;
    }
    return changed;
}

}  // namespace

void SettingsPanel::drawMedium(SceneDesc& scene) {
    MediumDesc fog = scene.medium;
    if (drawFog(fog)) setMedium(scene, fog);
    MediumDesc& m = scene.medium;
    const float maxC = lightscatter::limits::kMaxCoefficient;
    dragVec3("betaR (1/m)", m.betaR, 0.0f, maxC, "%.3e");
    dragVec3("betaM (1/m)", m.betaM, 0.0f, maxC, "%.3e");
    dragVec3("sigmaA (1/m)", m.sigmaA, 0.0f, maxC, "%.3e");
    ImGui::SliderFloat("g", &m.g, -0.99f, 0.99f, "%.3f");
    int phase = phaseIndex(m.phase);
    if (ImGui::Combo("phase", &phase, kPhases.data(), int(kPhases.size())))
        m.phase = phaseAt(phase);
    ImGui::DragFloat("max distance (m)", &m.maxDistance, 1.0f, 1e-3f, 1e8f, "%.4g",
                     ImGuiSliderFlags_Logarithmic);
}

}  // namespace host
