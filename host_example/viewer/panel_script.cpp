#include "panel_script.h"

#include <optional>
#include <stdexcept>

#include "scene/json_input.h"
#include "scene/medium_json.h"

namespace host {
namespace {

// A value in a settings file's terms as the number setFieldValue takes; empty when it is of the
// wrong kind.
std::optional<double> numberFor(const SettingField& f, const nlohmann::json& v, int component) {
    switch (f.kind) {
        case SettingField::Kind::Whole:
            if (v.is_number_unsigned()) return static_cast<double>(v.get<uint64_t>());
            return std::nullopt;
        case SettingField::Kind::Number:
            if (v.is_number()) return v.get<double>();
            return std::nullopt;
        case SettingField::Kind::Boolean:
            if (v.is_boolean()) return v.get<bool>() ? 1.0 : 0.0;
            return std::nullopt;
        case SettingField::Kind::Choice:
            if (v.is_string())
                for (size_t i = 0; i < f.choices.size(); ++i)
                    if (v.get<std::string>() == f.choices[i]) return static_cast<double>(i);
            return std::nullopt;
        case SettingField::Kind::Vector4:
            if (v.is_array() && v.size() == 4 && v[component].is_number())
                return v[component].get<double>();
            return std::nullopt;
    }
    return std::nullopt;
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
                if (!v.is_string() || !lightscatter::parseMethod(v.get<std::string>()))
                    fail(k, "method = " + v.dump() + ": not a method's name");
            } else if (key == "profile") {
                if (!v.is_string() || !lightscatter::parseProfile(v.get<std::string>()))
                    fail(k, "profile = " + v.dump() + ": not a profile's name");
            } else if (key == "save") {
                if (!v.is_string() || v.get<std::string>().empty())
                    fail(k, "save = " + v.dump() + ": must be a file name");
            } else if (key == "settings") {
                if (!v.is_object()) fail(k, "settings must be an object of fields");
                for (const auto& field : v.items()) {
                    const SettingField* f = findSettingField(field.key());
                    if (!f) fail(k, "settings." + field.key() + ": not a field of Settings");
                    const int n = f->kind == SettingField::Kind::Vector4 ? 4 : 1;
                    bool ok = true;
                    for (int c = 0; c < n; ++c) ok = ok && numberFor(*f, field.value(), c);
                    if (!ok)
                        fail(k, "settings." + field.key() + " = " + field.value().dump() +
                                    ": not a value of this field's kind");
                }
            } else if (key == "medium") {
                try {  // checked now against a default medium, applied over the scene's later
                    readMediumJson(v, path + ": step " + std::to_string(k), MediumDesc{});
                } catch (const SceneError& e) {
                    throw std::runtime_error(e.what());
                }
            } else {
                fail(k,
                     "unknown key '" + key + "' (known: method, profile, settings, medium, save)");
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
    if (step.contains("method"))
        panel.setMethod(o, *lightscatter::parseMethod(step["method"].get<std::string>()));
    if (step.contains("profile"))
        panel.setProfile(o, *lightscatter::parseProfile(step["profile"].get<std::string>()));
    if (step.contains("settings"))
        for (const auto& field : step["settings"].items()) {
            const SettingField& f = *findSettingField(field.key());
            const int components = f.kind == SettingField::Kind::Vector4 ? 4 : 1;
            for (int c = 0; c < components; ++c)
                panel.setField(o, f, *numberFor(f, field.value(), c), c);
        }
    if (step.contains("medium"))
        panel.setMedium(scene, readMediumJson(step["medium"], path_, scene.medium));
    if (step.contains("save")) panel.save(o, step["save"].get<std::string>());
}

}  // namespace host
