#include "panel_script.h"

#include <stdexcept>

#include "scene/json_input.h"
#include "scene/medium_json.h"

namespace host {
namespace {

// A method's name or a preset's ("froxels-unreal"), as --method takes them.
bool isMethodOrPreset(const std::string& name) {
    lightscatter::Settings scratch;
    return lightscatter::parseMethod(name) || lightscatter::applyMethodPreset(name, scratch);
}

// The value as a settings file sets it (settings_fields.h), into a copy of `base`: a value of the
// wrong kind, an integer out of its field's range or a number no float holds is refused here with
// the settings file's words, never clamped or rounded to another value on the way.
lightscatter::Settings withValue(const lightscatter::Settings& base, const SettingField& f,
                                 const nlohmann::json& v, const std::string& key) {
    lightscatter::Settings s = base;
    setFieldFromJson(s, f, v, key);
    return s;
}

// Each field whose value `s` changes, set through the panel (as its widgets set it).
void setChanged(SettingsPanel& panel, RenderOptions& o, const lightscatter::Settings& s) {
    const lightscatter::Settings before = SettingsPanel::effective(o);
    for (const SettingField& f : settingFields()) {
        const int components = f.kind == SettingField::Kind::Vector4 ? 4 : 1;
        for (int c = 0; c < components; ++c)
            if (fieldValue(s, f, c) != fieldValue(before, f, c))
                panel.setField(o, f, fieldValue(s, f, c), c);
    }
}

}  // namespace

PanelScript::PanelScript(const std::string& path) : path_(path) {
    nlohmann::json root;
    try {
        root = readJsonFile(path, "panel script", 1024 * 1024);
    } catch (const JsonInputError& e) {
        throw std::runtime_error(e.what());
    }
    auto fail = [&](size_t k, const std::string& what) {
        throw std::runtime_error(path + ": step " + std::to_string(k) + ": " + what);
    };
    if (!root.is_array()) throw std::runtime_error(path + ": must be an array of steps");
    for (size_t k = 0; k < root.size(); ++k) {
        const nlohmann::json& step = root[k];
        if (!step.is_object()) fail(k, "must be an object");
        for (const auto& item : step.items()) {
            const std::string& key = item.key();
            const nlohmann::json& v = item.value();
            if (key == "method") {
                if (!v.is_string() || !isMethodOrPreset(v.get<std::string>()))
                    fail(k, "method = " + echo(v) + ": not a method's or a preset's name");
            } else if (key == "profile") {
                if (!v.is_string() || !lightscatter::parseProfile(v.get<std::string>()))
                    fail(k, "profile = " + echo(v) + ": not a profile's name");
            } else if (key == "save") {
                if (!v.is_string() || v.get<std::string>().empty())
                    fail(k, "save = " + echo(v) + ": must be a file name");
            } else if (key == "settings") {
                if (!v.is_object()) fail(k, "settings must be an object of fields");
                for (const auto& field : v.items()) {
                    const std::string name = "settings." + echoText(field.key());
                    const SettingField* f = findSettingField(field.key());
                    if (!f) fail(k, name + ": not a field of Settings");
                    try {
                        (void)withValue({}, *f, field.value(), name);
                    } catch (const std::runtime_error& e) {
                        fail(k, e.what());
                    }
                }
            } else if (key == "medium") {
                try {  // checked now against a default medium, applied over the scene's later
                    readMediumJson(v, path + ": step " + std::to_string(k), MediumDesc{});
                } catch (const SceneError& e) {
                    throw std::runtime_error(e.what());
                }
            } else {
                fail(k, "unknown key '" + echoText(key) +
                            "' (known: method, profile, settings, medium, save)");
            }
        }
        steps_.push_back(step);
    }
}

std::vector<std::pair<size_t, std::string>> PanelScript::saves() const {
    std::vector<std::pair<size_t, std::string>> list;
    for (size_t k = 0; k < steps_.size(); ++k)
        if (steps_[k].contains("save")) list.emplace_back(k, steps_[k]["save"].get<std::string>());
    return list;
}

void PanelScript::apply(size_t k, SettingsPanel& panel, RenderOptions& o, SceneDesc& scene) const {
    if (k >= steps_.size()) return;
    const nlohmann::json& step = steps_[k];
    if (step.contains("method")) {
        const std::string name = step["method"].get<std::string>();
        // A preset is its method with its settings, as --method takes it.
        lightscatter::Settings preset = SettingsPanel::effective(o);
        if (const auto m = lightscatter::applyMethodPreset(name, preset)) {
            setChanged(panel, o, preset);
            panel.setMethod(o, *m);
        } else {
            panel.setMethod(o, *lightscatter::parseMethod(name));
        }
    }
    if (step.contains("profile"))
        panel.setProfile(o, *lightscatter::parseProfile(step["profile"].get<std::string>()));
    if (step.contains("settings"))
        for (const auto& field : step["settings"].items()) {
            const SettingField& f = *findSettingField(field.key());
            const lightscatter::Settings s =
                withValue(SettingsPanel::effective(o), f, field.value(), field.key());
            const int components = f.kind == SettingField::Kind::Vector4 ? 4 : 1;
            for (int c = 0; c < components; ++c) panel.setField(o, f, fieldValue(s, f, c), c);
        }
    if (step.contains("medium"))
        panel.setMedium(scene, readMediumJson(step["medium"], path_, scene.medium));
    if (step.contains("save")) panel.save(o, step["save"].get<std::string>());
}

}  // namespace host
