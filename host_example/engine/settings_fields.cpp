#include "settings_fields.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "scene/json_input.h"

namespace host {
namespace {

using Kind = SettingField::Kind;

// A float as the shortest decimal that reads back to it (0.03, not 0.029999999329447746).
double shortest(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf - 1, static_cast<float>(v));
    *r.ptr = '\0';
    return std::strtod(buf, nullptr);
}

[[noreturn]] void refuse(const std::string& key, const nlohmann::json& v, const std::string& rule) {
    throw std::runtime_error(key + " = " + echo(v) + ": must be " + rule);
}

uint32_t whole(const nlohmann::json& v, const std::string& key) {
    const bool negative = v.is_number_integer() && !v.is_number_unsigned() && v.get<int64_t>() < 0;
    if (!v.is_number_integer() || negative ||
        v.get<uint64_t>() > std::numeric_limits<uint32_t>::max())
        refuse(key, v, "a whole number from 0 to 4294967295");
    return static_cast<uint32_t>(v.get<uint64_t>());
}

float number(const nlohmann::json& v, const std::string& key) {
    if (!v.is_number()) refuse(key, v, "a number");
    const double d = v.get<double>();
    // FLT_MAX is written as the shortest text that reads back as it, 3.4028235e+38, which as a
    // double lies above it: any value that rounds to a finite float is that float. Half an ulp
    // above FLT_MAX (2^103) rounds to infinity.
    constexpr double kFloatMax = std::numeric_limits<float>::max();
    constexpr double kRoundsToFloatMax = kFloatMax + 0x1p103;
    if (!std::isfinite(d) || std::fabs(d) >= kRoundsToFloatMax) refuse(key, v, "a finite number");
    return static_cast<float>(std::clamp(d, -kFloatMax, kFloatMax));
}

}  // namespace

void setFieldFromJson(lightscatter::Settings& s, const SettingField& f, const nlohmann::json& v,
                      const std::string& key) {
    switch (f.kind) {
        case Kind::Whole:
            setFieldValue(s, f, whole(v, key));
            return;
        case Kind::Number:
            setFieldValue(s, f, number(v, key));
            return;
        case Kind::Boolean:
            if (!v.is_boolean()) refuse(key, v, "true or false");
            setFieldValue(s, f, v.get<bool>() ? 1.0 : 0.0);
            return;
        case Kind::Choice: {
            std::string names;
            for (size_t i = 0; i < f.choices.size(); ++i) {
                if (v.is_string() && v.get<std::string>() == f.choices[i]) {
                    setFieldValue(s, f, static_cast<double>(i));
                    return;
                }
                names += (names.empty() ? "" : ", ") + f.choices[i];
            }
            refuse(key, v, "one of " + names);
        }
        case Kind::Vector4: {
            if (!v.is_array() || v.size() != 4) refuse(key, v, "an array of 4 numbers");
            for (int c = 0; c < 4; ++c)
                setFieldValue(
                    s, f, number(v[static_cast<size_t>(c)], key + "[" + std::to_string(c) + "]"),
                    c);
            return;
        }
    }
}

std::string knownFieldNames() {
    std::string s;
    for (const SettingField& f : settingFields()) s += (s.empty() ? "" : ", ") + f.name;
    return s + "; or a field's flat name before 0.4";
}

const std::vector<SettingField>& settingFields() {
    return lightscatter::settingsFields();
}

const SettingField* findSettingField(const std::string& name) {
    return lightscatter::findSettingsField(name);
}

std::string fieldGroup(const SettingField& f) {
    const size_t dot = f.name.find('.');
    return dot == std::string::npos ? std::string() : f.name.substr(0, dot);
}

std::string fieldKey(const SettingField& f) {
    const size_t dot = f.name.find('.');
    return dot == std::string::npos ? f.name : f.name.substr(dot + 1);
}

double fieldValue(const lightscatter::Settings& s, const SettingField& f, int component) {
    return f.get(s, component);
}

void setFieldValue(lightscatter::Settings& s, const SettingField& f, double value, int component) {
    if (f.kind == Kind::Choice)
        value = std::clamp(std::round(value), 0.0, static_cast<double>(f.choices.size()) - 1);
    f.set(s, value, component);
}

nlohmann::json fieldJson(const lightscatter::Settings& s, const SettingField& f) {
    switch (f.kind) {
        case Kind::Whole:
            return static_cast<uint64_t>(f.get(s, 0));
        case Kind::Number:
            return shortest(f.get(s, 0));
        case Kind::Boolean:
            return f.get(s, 0) != 0.0;
        case Kind::Choice: {
            const auto i = static_cast<size_t>(f.get(s, 0));
            return i < f.choices.size() ? f.choices[i] : "unknown";
        }
        case Kind::Vector4: {
            nlohmann::json a = nlohmann::json::array();
            for (int c = 0; c < 4; ++c) a.push_back(shortest(f.get(s, c)));
            return a;
        }
    }
    return nullptr;
}

std::string settingsFileText(const lightscatter::Settings& s) {
    nlohmann::json out = nlohmann::json::object();
    for (const SettingField& f : settingFields()) {
        const std::string group = fieldGroup(f);
        if (group.empty())
            out[f.name] = fieldJson(s, f);
        else
            out[group][fieldKey(f)] = fieldJson(s, f);
    }
    return out.dump(2) + "\n";
}

}  // namespace host
