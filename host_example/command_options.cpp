#include "command_options.h"

#include <stdexcept>

#include "settings_file.h"

namespace host {
namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
}

}  // namespace

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
    const auto m = lightscatter::parseMethod(method);
    if (!m)
        throw std::runtime_error("unknown method '" + method +
                                 "' (known: " + joined(lightscatter::methodNames()) + ")");
    const std::string profile = args.take("--profile", "balanced");
    o.settingsPath = args.take("--settings", "");
    o.render = profileOptions(profile, o.settingsPath);
    o.render.method = *m;
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
