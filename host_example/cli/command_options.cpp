#include "command_options.h"

#include <cstdio>
#include <stdexcept>

#include "settings_file.h"

namespace host {

std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
}

namespace {

// The way nlohmann writes a float read from JSON: 0.5, not 0.500000.
std::string shortNumber(float x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", static_cast<double>(x));
    return buf;
}

}  // namespace

std::string methodsHonouring(bool lightscatter::MethodInfo::*what, bool andAuto) {
    std::vector<std::string> names;
    for (const lightscatter::MethodInfo& m : lightscatter::methodInfo())
        if (m.*what) names.push_back(m.name);
    if (andAuto) names.emplace_back("auto");
    std::string s;
    for (size_t i = 0; i < names.size(); ++i)
        s += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return s;
}

std::vector<std::string> methodAndPresetNames() {
    std::vector<std::string> known = lightscatter::methodNames();
    for (const lightscatter::MethodInfo& m : lightscatter::methodInfo())
        for (const lightscatter::MethodPreset& p : m.presets) known.push_back(p.name);
    return known;
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
            "fields by name (e.g. {\"epipolar\": {\"slices\": 512}}; see "
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
    const std::string profile = args.take("--profile", "balanced");
    o.settingsPath = args.take("--settings", "");
    o.render = profileOptions(profile, o.settingsPath);
    // A method's preset ("froxels-unreal") is its method with the preset's settings.
    const auto preset = lightscatter::applyMethodPreset(method, o.render.custom);
    const auto m = preset ? preset : lightscatter::parseMethod(method);
    if (!m)
        throw std::runtime_error("unknown method '" + method +
                                 "' (known: " + joined(methodAndPresetNames()) + ")");
    o.render.method = *m;
    // Known before any device exists: the plugin would refuse a frame whose method does not
    // honour these (auto picks one that does).
    const float noise = o.render.custom.noiseAmplitude;
    if (noise > 0.0f && !honours(*m, &lightscatter::MethodInfo::noise))
        throw std::runtime_error(
            o.settingsPath + ": noiseAmplitude = " + shortNumber(noise) +
            ": seed 002's scrolling noise is honoured by " +
            methodsHonouring(&lightscatter::MethodInfo::noise) + " only; --method " + method +
            " integrates the model's homogeneous medium (use one of them or auto, or "
            "noiseAmplitude 0)");
    if (o.render.custom.lightModel == lightscatter::LightModel::Simplified &&
        !honours(*m, &lightscatter::MethodInfo::simplifiedModel))
        throw std::runtime_error(
            o.settingsPath + ": lightModel = \"simplified\": seed 004's simplified light model " +
            "is honoured by " + methodsHonouring(&lightscatter::MethodInfo::simplifiedModel) +
            " only; --method " + method +
            " integrates the full model (use one of them or auto, or lightModel \"full\")");
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
