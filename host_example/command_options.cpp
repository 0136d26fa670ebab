#include "command_options.h"

#include <stdexcept>

namespace host {
namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
}

}  // namespace

SceneOptions takeSceneOptions(Args& args, const char* defaultSize) {
    SceneOptions o;
    const std::string method = args.take("--method", "epipolar");
    const auto m = lightscatter::parseMethod(method);
    if (!m) throw std::runtime_error("unknown method '" + method + "' (known: " + joined(lightscatter::methodNames()) + ")");
    o.render.method = *m;
    const std::string profile = args.take("--profile", "balanced");
    const auto p = lightscatter::parseProfile(profile);
    if (!p || *p == lightscatter::Profile::Custom)
        throw std::runtime_error("unknown profile '" + profile + "' (known: " +
                                 joined(lightscatter::profileNames()) + ", custom only through the API)");
    o.render.profile = *p;
    const std::string size = args.take("--size", defaultSize ? defaultSize : "");
    if (!size.empty()) o.size = parseSize(size, "--size");
    o.device.deviceName = args.take("--device", "");
    o.device.validation = args.flag("--validation");
    return o;
}

VkExtent2D sceneSize(const SceneOptions& o, VkExtent2D fallback) { return o.size ? *o.size : fallback; }

}  // namespace host
