#include "settings_fields.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

namespace host {
namespace {

using lightscatter::Settings;
using Kind = SettingField::Kind;

SettingField whole(const char* name, uint32_t Settings::*m, double lo, double hi, const char* help,
                   bool profileSized = false) {
    SettingField f{name, Kind::Whole, lo, hi, false, profileSized, {}, help};
    f.get = [m](const Settings& s, int) { return static_cast<double>(s.*m); };
    f.set = [m](Settings& s, double v, int) {
        s.*m = static_cast<uint32_t>(std::clamp(std::round(v), 0.0, 4294967295.0));
    };
    return f;
}

SettingField number(const char* name, float Settings::*m, double lo, double hi, bool logarithmic,
                    const char* help) {
    SettingField f{name, Kind::Number, lo, hi, logarithmic, false, {}, help};
    f.get = [m](const Settings& s, int) { return static_cast<double>(s.*m); };
    f.set = [m](Settings& s, double v, int) { s.*m = static_cast<float>(v); };
    return f;
}

SettingField boolean(const char* name, bool Settings::*m, const char* help) {
    SettingField f{name, Kind::Boolean, 0, 1, false, false, {}, help};
    f.get = [m](const Settings& s, int) { return s.*m ? 1.0 : 0.0; };
    f.set = [m](Settings& s, double v, int) { s.*m = v != 0.0; };
    return f;
}

template <class Enum>
SettingField choice(const char* name, Enum Settings::*m, std::vector<const char*> names,
                    const char* help, bool profileSized = false) {
    const double last = static_cast<double>(names.size()) - 1;
    SettingField f{name, Kind::Choice, 0, last, false, profileSized, std::move(names), help};
    f.get = [m](const Settings& s, int) { return static_cast<double>(s.*m); };
    f.set = [m, last](Settings& s, double v, int) {
        s.*m = static_cast<Enum>(static_cast<int>(std::clamp(std::round(v), 0.0, last)));
    };
    return f;
}

SettingField vector4(const char* name, std::array<float, 4> Settings::*m, double lo, double hi,
                     const char* help) {
    SettingField f{name, Kind::Vector4, lo, hi, false, false, {}, help};
    f.get = [m](const Settings& s, int c) { return static_cast<double>((s.*m)[c & 3]); };
    f.set = [m](Settings& s, double v, int c) { (s.*m)[c & 3] = static_cast<float>(v); };
    return f;
}

// A float as the shortest decimal that reads back to it (0.03, not 0.029999999329447746).
double shortest(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf - 1, static_cast<float>(v));
    *r.ptr = '\0';
    return std::strtod(buf, nullptr);
}

// The choices' names are the settings file's; their order is the enum's.
std::vector<SettingField> makeFields() {
    namespace L = lightscatter::limits;
    return {
        whole("slices", &Settings::slices, 4, 4096, "epipolar lines, a multiple of 4", true),
        whole("samplesPerSlice", &Settings::samplesPerSlice, 2, 4096, "samples along each line",
              true),
        whole("initialSampleStep", &Settings::initialSampleStep, 1, 128,
              "ray-marching samples every N samples (a power of two)"),
        number("refinementThreshold", &Settings::refinementThreshold, 1e-4, 1, true,
               "relative camera-z jump that is a depth break"),
        number("inscatterRefinementThreshold", &Settings::inscatterRefinementThreshold, 0, 1, false,
               "march between samples whose in-scattering differs this much (0: off)"),
        number("bilateralThreshold", &Settings::bilateralThreshold, 1e-4, 1, true,
               "relative camera-z difference the unwarp accepts"),
        boolean("minMaxTrees", &Settings::minMaxTrees, "1D min/max binary trees per slice"),
        choice("shadowFilter", &Settings::shadowFilter, {"nearest", "bilinear"},
               "shadow-map look-ups: nearest texel or 2x2 PCF"),
        boolean("fixup", &Settings::fixup, "ray-march the pixels the unwarp cannot interpolate"),
        whole("fixupMaxSteps", &Settings::fixupMaxSteps, 0, 4096,
              "at most this many steps per fix-up pixel (0: every texel)"),
        number("shadowDepthBias", &Settings::shadowDepthBias, -0.01, 0.01, false,
               "added to the ray's light-space depth"),
        choice("interpolation", &Settings::interpolation, {"shadowed-fraction", "inscattering"},
               "what epipolar samples carry to the screen"),
        whole("shadowMapSize", &Settings::shadowMapSize, 1, 16384,
              "the profile's recommended shadow map", true),
        whole("coneSamples", &Settings::coneSamples, 1, 4096, "cone-march: samples per pixel"),
        boolean("coneLimited", &Settings::coneLimited,
                "cone-march: only the ray's part in the cone"),
        boolean("coneJitter", &Settings::coneJitter, "cone-march: jittered sample offsets"),
        boolean("shadowSampling", &Settings::shadowSampling,
                "false: seed 003's mode without shadow look-ups (cone-march only)"),
        whole("planeCount", &Settings::planeCount, 2, 4096, "planes across the light's volume",
              true),
        number("planeSpacing", &Settings::planeSpacing, 0, 10, false,
               "planes at most this far apart, metres (0: planeCount)"),
        choice("planeTarget", &Settings::planeTarget, {"float16", "float32", "rgba8"},
               "what the planes blend into", true),
        boolean("planeScaling", &Settings::planeScaling,
                "fewer planes as the light's volume shrinks on screen"),
        number("planeRange", &Settings::planeRange, 0, 1e3, false,
               "rgba8: the luminance that fills the channels (0: from the light)"),
        boolean("planeDither", &Settings::planeDither, "rgba8: stochastic rounding"),
        whole("planeBlur", &Settings::planeBlur, 0, 8, "blur at composite, pixels"),
        number("planeAmbient", &Settings::planeAmbient, 0, 10, false,
               "ambient term beside the inverse square, 1/m^2"),
        number("noiseAmplitude", &Settings::noiseAmplitude, 0, 1, false,
               "scrolling noise (planes only)"),
        number("noiseScale", &Settings::noiseScale, 1e-3, 1e3, true, "a noise tile's size"),
        vector4("noiseVelocity", &Settings::noiseVelocity, -1, 1, "tiles per second, two layers"),
        choice("lightModel", &Settings::lightModel, {"full", "simplified"},
               "seed 004's simplified model (analytic, beam-tree-analytic)"),
        number("simplifiedA0", &Settings::simplifiedA0, 0, 1, false,
               "a0 of I / (a1 r^2 + a0), m^2"),
        number("simplifiedA1", &Settings::simplifiedA1, L::kMinSimplifiedA1, L::kMaxSimplifiedA1,
               true, "a1 of I / (a1 r^2 + a0)"),
        whole("froxelTile", &Settings::froxelTile, 2, 64, "froxels: a column's pixels"),
        whole("froxelSlices", &Settings::froxelSlices, 4, 512, "froxels: depth slices"),
        number("froxelFarDistance", &Settings::froxelFarDistance, 0, 1000, false,
               "froxels: the grid's far end, metres (0: the medium's)"),
        boolean("froxelTemporal", &Settings::froxelTemporal,
                "froxels: jitter and blend with the previous frame"),
        number("froxelHistoryWeight", &Settings::froxelHistoryWeight, 0, 0.99, false,
               "froxels: the history's weight in the blend"),
    };
}

}  // namespace

const std::vector<SettingField>& settingFields() {
    static const std::vector<SettingField> fields = makeFields();
    return fields;
}

const SettingField* findSettingField(const std::string& name) {
    for (const SettingField& f : settingFields())
        if (name == f.name) return &f;
    return nullptr;
}

double fieldValue(const lightscatter::Settings& s, const SettingField& f, int component) {
    return f.get(s, component);
}

void setFieldValue(lightscatter::Settings& s, const SettingField& f, double value, int component) {
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
    for (const SettingField& f : settingFields()) out[f.name] = fieldJson(s, f);
    return out.dump(2) + "\n";
}

}  // namespace host
