// A frame's settings against the fields' tables (lightscatter::settingsFields()): the one check of
// every field, and the profiles' values.
#include <charconv>
#include <cmath>
#include <cstdio>

#include <lightscatter/lightscatter.h>
#include "enum_checks.h"
#include "shared/settings_table.h"

namespace lightscatter {
namespace {

[[noreturn]] void fail(const std::string& message) {
    throw InvalidInput("lightscatter: " + message);
}

std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// A Number's or Vector4's fields are floats: each is compared with the floats nearest its bounds,
// so that a value written as a bound (0.99, 1e-6, 1e30) is accepted, and both are quoted as the
// shortest text that reads back as that float ("0.99000001" is refused beside "0.99"). A Whole is
// an integer, which a double holds exactly: it is compared and quoted as one.
bool isFloat(const SettingsField& f) {
    return f.kind == SettingsField::Kind::Number || f.kind == SettingsField::Kind::Vector4;
}

double asCompared(const SettingsField& f, double v) {
    return isFloat(f) ? static_cast<double>(static_cast<float>(v)) : v;
}

std::string text(const SettingsField& f, double v) {
    char buf[64];
    const auto r = isFloat(f) ? std::to_chars(buf, buf + sizeof buf, static_cast<float>(v))
                              : std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

// The rule's values in words: "in [1, 128]", "> 0 and finite", "0 or in [1e-06, 1e+08]".
std::string bounds(const SettingsField& f) {
    const bool finiteOnly = f.max >= ls::kFiniteMax;
    const std::string lo = text(f, f.min), hi = text(f, f.max);
    std::string b;
    if (finiteOnly && f.min <= -ls::kFiniteMax)
        b = "finite";
    else if (finiteOnly)
        b = (f.minExclusive ? "> " : ">= ") + lo + " and finite";
    else
        b = "in " + std::string(f.minExclusive ? "(" : "[") + lo + ", " + hi + "]";
    return f.zeroIsOff ? "0 or " + b : b;
}

bool inBounds(const SettingsField& f, double v) {
    if (!std::isfinite(v)) return false;
    if (f.zeroIsOff && v == 0.0) return true;
    const double lo = asCompared(f, f.min), hi = asCompared(f, f.max);
    v = asCompared(f, v);
    return (f.minExclusive ? v > lo : v >= lo) && v <= hi;
}

void checkField(const Settings& s, const SettingsField& f, const std::string& path) {
    const std::string why = f.rule.empty() ? std::string() : " (" + f.rule + ")";
    switch (f.kind) {
        case SettingsField::Kind::Boolean:
            return;
        case SettingsField::Kind::Choice: {
            const double v = f.get(s, 0);
            if (v >= 0.0 && v < static_cast<double>(f.choices.size())) return;
            std::string names;
            for (const std::string& c : f.choices) names += (names.empty() ? "" : ", ") + c;
            fail(path + " = " + num(v) + ": must be one of " + names + " (by their order)");
        }
        case SettingsField::Kind::Whole: {
            const double v = f.get(s, 0);
            const auto w = static_cast<uint64_t>(v);
            if (f.powerOfTwo && (w == 0 || (w & (w - 1)) != 0 || !inBounds(f, v)))
                fail(path + " = " + text(f, v) + ": must be a power of two " + bounds(f) + why);
            if (f.multipleOf > 1 && (w % f.multipleOf != 0 || !inBounds(f, v)))
                fail(path + " = " + text(f, v) + ": must be a multiple of " +
                     std::to_string(f.multipleOf) + " " + bounds(f) + why);
            if (!inBounds(f, v)) fail(path + " = " + text(f, v) + ": must be " + bounds(f) + why);
            return;
        }
        case SettingsField::Kind::Number: {
            const double v = f.get(s, 0);
            if (!inBounds(f, v)) fail(path + " = " + text(f, v) + ": must be " + bounds(f) + why);
            return;
        }
        case SettingsField::Kind::Vector4:
            for (int c = 0; c < 4; ++c) {
                const double v = f.get(s, c);
                if (!inBounds(f, v))
                    fail(path + "[" + std::to_string(c) + "] = " + text(f, v) + ": must be " +
                         bounds(f) + why);
            }
            return;
    }
}

}  // namespace

void checkSettings(const Settings& s, const std::string& at) {
    for (const SettingsField& f : settingsFields())
        checkField(s, f, at.empty() ? f.name : at + "." + f.name);
}

Settings profileSettings(Profile profile) {
    return profileSettings(profile, Settings{});
}

// Everything is the engine's (custom) but what the profile decides: a field added to a table is
// the engine's without a word here.
Settings profileSettings(Profile profile, const Settings& custom) {
    // Refused rather than taken as Custom: a profile the engine meant would silently not apply.
    detail::checkProfile(profile, "profile");
    Settings s = custom;
    const auto p = static_cast<size_t>(profile);
    if (p >= kSizedProfiles) return s;  // Custom
    for (const SettingsField& f : settingsFields())
        if (f.profileSized) f.set(s, f.profileValues[p], 0);
    return s;
}

}  // namespace lightscatter
