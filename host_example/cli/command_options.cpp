#include "command_options.h"

#include <cstdio>
#include <stdexcept>

#include "settings_file.h"

namespace host {
namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
}

// The way nlohmann writes a float read from JSON: 0.5, not 0.500000.
std::string shortNumber(float x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", static_cast<double>(x));
    return buf;
}

}  // namespace

bool honoursNoise(lightscatter::Method method) {
    return method == lightscatter::Method::Planes || method == lightscatter::Method::Auto;
}

bool honoursLightModel(lightscatter::Method method) {
    return method == lightscatter::Method::BeamTreeAnalytic ||
           method == lightscatter::Method::Analytic || method == lightscatter::Method::Auto;
}

RenderOptions profileOptions(const std::string& profile, const std::string& settingsPath) {
    RenderOptions o;
    const auto p = lightscatter::parseProfile(profile);
    if (!p)
        throw std::runtime_error("unknown profile '" + profile +
                                 "' (known: " + joined(lightscatter::profileNames()) + ")");
    if (*p == lightscatter::Profile::Custom && settingsPath.empty())
        throw std::runtime_error(
            "--profile custom needs --settings FILE.json, a JSON object of lightscatter::Settings "
            "fields by name (e.g. {\"slices\": 512, \"samplesPerSlice\": 256}; see "
            "docs/host_example.md)");
    o.profile = *p;
    if (!settingsPath.empty()) {
        // Custom starts from lightscatter::Settings' defaults, any other profile from its own.
        o.custom = loadSettingsFile(settingsPath, lightscatter::profileSettings(*p));
        o.profile = lightscatter::Profile::Custom;
    }
    return o;
}

SceneOptions takeSceneOptions(Args& args, const char* defaultSize) {
    SceneOptions o;
    const std::string method = args.take("--method", "auto");
    // A froxel preset ("froxels-hdrp", "froxels-unreal") is froxels with the preset's grid.
    lightscatter::Settings preset;
    const bool froxelPreset = lightscatter::applyFroxelPreset(method, preset);
    const auto m = froxelPreset ? lightscatter::Method::Froxels : lightscatter::parseMethod(method);
    if (!m) {
        std::vector<std::string> known = lightscatter::methodNames();
        for (const auto& p : lightscatter::froxelPresets()) known.emplace_back(p.name);
        throw std::runtime_error("unknown method '" + method + "' (known: " + joined(known) + ")");
    }
    const std::string profile = args.take("--profile", "balanced");
    o.settingsPath = args.take("--settings", "");
    o.render = profileOptions(profile, o.settingsPath);
    o.render.method = *m;
    if (froxelPreset) {
        o.render.custom.froxelTile = preset.froxelTile;
        o.render.custom.froxelSlices = preset.froxelSlices;
        o.render.custom.froxelTemporal = preset.froxelTemporal;
    }
    // Known before any device exists: seed 002's noise is a density only seed 002's planes sample
    // (auto picks them when it is on); the plugin would refuse every other method's frame.
    const float noise = o.render.custom.noiseAmplitude;
    if (noise > 0.0f && !honoursNoise(*m))
        throw std::runtime_error(
            o.settingsPath + ": noiseAmplitude = " + shortNumber(noise) +
            ": seed 002's scrolling noise is honoured by method planes only; --method " + method +
            " integrates the model's homogeneous medium (use --method planes or auto, or "
            "noiseAmplitude 0)");
    if (o.render.custom.lightModel == lightscatter::LightModel::Simplified &&
        !honoursLightModel(*m))
        throw std::runtime_error(
            o.settingsPath + ": lightModel = \"simplified\": seed 004's simplified light model " +
            "is honoured by methods beam-tree-analytic and analytic only; --method " + method +
            " integrates the full model (use --method beam-tree-analytic, analytic or auto, or " +
            "lightModel \"full\")");
    const std::string size = args.take("--size", defaultSize ? defaultSize : "");
    if (!size.empty()) o.size = parseSize(size, "--size");
    o.device.deviceName = args.take("--device", "");
    o.device.validation = args.flag("--validation");
    return o;
}

VkExtent2D sceneSize(const SceneOptions& o, VkExtent2D fallback) {
    return o.size ? *o.size : fallback;
}

}  // namespace host
