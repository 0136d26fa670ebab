#pragma once
// Every field of lightscatter::Settings by the name a settings file gives it: its kind, the range a
// slider offers, the names of its choices. One list, read by the settings file (reading and
// writing) and by the viewer's panel, so that a field added to Settings is added once here. The
// plugin's own validation stays the judge of what is valid; the ranges here only bound a slider.
#include <functional>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include <nlohmann/json_fwd.hpp>

namespace host {

struct SettingField {
    enum class Kind { Whole, Number, Boolean, Choice, Vector4 };
    const char* name;
    Kind kind;
    double min = 0.0, max = 0.0;  // the slider's ends (Whole, Number, Vector4's components)
    bool logarithmic = false;     // a slider over decades (thresholds, scales)
    // A profile other than custom decides it (slices, samplesPerSlice, shadowMapSize, planeCount,
    // planeTarget): editing it means running the custom profile.
    bool profileSized = false;
    std::vector<const char*> choices;  // Choice: the names, in the enum's order
    const char* help = "";             // one line for the panel's tooltip
    // The value as a number (fieldValue's terms) and back.
    std::function<double(const lightscatter::Settings&, int component)> get;
    std::function<void(lightscatter::Settings&, double value, int component)> set;
};

const std::vector<SettingField>& settingFields();
// The field of that name, or null.
const SettingField* findSettingField(const std::string& name);

// A field's value as a number: Whole and Number as they are, Boolean 0 or 1, Choice the index of
// its name, Vector4 the component `component`.
double fieldValue(const lightscatter::Settings& s, const SettingField& f, int component = 0);
// Sets a field from a number as fieldValue gives it (a Whole rounded, a Choice's index clamped).
void setFieldValue(lightscatter::Settings& s, const SettingField& f, double value,
                   int component = 0);

// The field as a settings file writes it (a number, true or false, a choice's name, an array).
nlohmann::json fieldJson(const lightscatter::Settings& s, const SettingField& f);
// Every field of `s`, as a settings file that loadSettingsFile reads back to `s`.
std::string settingsFileText(const lightscatter::Settings& s);

}  // namespace host
