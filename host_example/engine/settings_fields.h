#pragma once
// The fields of lightscatter::Settings as the host's settings files, panel and benchmark name them:
// the plugin's own tables (lightscatter::settingsFields(), each method's declared in its folder),
// so that a field or a method added to the plugin is in every file and panel without a word here.
// A settings file nests each method's fields under its member ({"epipolar": {"slices": 512}});
// a key may also be a field's dotted name ("epipolar.slices") or its former flat name ("slices").
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include <nlohmann/json_fwd.hpp>

namespace host {

using SettingField = lightscatter::SettingsField;

const std::vector<SettingField>& settingFields();
// The field of that dotted or former name, or null.
const SettingField* findSettingField(const std::string& name);
// The group a field is nested under in a settings file ("epipolar"; empty for Settings' own) and
// its key there ("slices").
std::string fieldGroup(const SettingField& f);
std::string fieldKey(const SettingField& f);

// A field's value as a number: Whole and Number as they are, Boolean 0 or 1, Choice the index of
// its name, Vector4 the component `component`.
double fieldValue(const lightscatter::Settings& s, const SettingField& f, int component = 0);
// Sets a field from a number as fieldValue gives it (a Whole rounded, a Choice's index clamped).
void setFieldValue(lightscatter::Settings& s, const SettingField& f, double value,
                   int component = 0);

// Sets the field from a settings file's value (a whole number, a finite number, true or false, a
// choice's name, an array of four numbers); throws std::runtime_error "KEY = VALUE: must be ..."
// naming it as `key` when the value is not of the field's kind. The plugin's own rules (ranges)
// are lightscatter::checkSettings'.
void setFieldFromJson(lightscatter::Settings& s, const SettingField& f, const nlohmann::json& v,
                      const std::string& key);
// The names a settings file, a benchmark's configuration or a panel script may give fields: each
// field's (and, said in a word, their former names).
std::string knownFieldNames();

// The field as a settings file writes it (a number, true or false, a choice's name, an array).
nlohmann::json fieldJson(const lightscatter::Settings& s, const SettingField& f);
// Every field of `s`, as a settings file that loadSettingsFile reads back to `s`.
std::string settingsFileText(const lightscatter::Settings& s);

}  // namespace host
