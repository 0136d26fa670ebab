// lightscatter budget [--method NAME] [--profile NAME|all] [--settings FILE.json]
//   [--size WxH] [--shadow-map N] [--lights sun,spot:unshadowed,point:brute-force,...]
//   [--color FORMAT] [--json]
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "command_options.h"
#include "commands.h"
#include "rendergraph/format_info.h"
#include "scene/json_input.h"
#include "settings_fields.h"
#include "settings_file.h"

namespace host {
namespace {

double mib(uint64_t bytes) {
    return static_cast<double>(bytes) / (1024.0 * 1024.0);
}

// A method or a preset's (MethodInfo::presets), whose settings go into `settings`.
lightscatter::Method budgetMethod(const std::string& name, lightscatter::Settings& settings) {
    if (const auto preset = lightscatter::applyMethodPreset(name, settings)) return *preset;
    if (const auto m = lightscatter::parseMethod(name); m && *m != lightscatter::Method::Auto)
        return *m;
    std::vector<std::string> known = methodAndPresetNames();
    known.erase(std::remove(known.begin(), known.end(), "auto"), known.end());
    throw std::runtime_error("unknown method '" + name + "' (budget knows: " + joined(known) + ")");
}

// The method's own settings a budget shows: those the profile decides, or all of them.
std::vector<const SettingField*> shownFields(lightscatter::Method method) {
    std::vector<const SettingField*> own, sized;
    for (const lightscatter::MethodInfo& m : lightscatter::methodInfo())
        if (m.method == method)
            for (const SettingField& f : m.settings) {
                own.push_back(findSettingField(f.name));
                if (f.profileSized) sized.push_back(own.back());
            }
    return sized.empty() ? own : sized;
}

// --color: the engine's color format by its Vulkan name less VK_FORMAT_, among those engines
// render to.
VkFormat parseColorFormat(const std::string& name) {
    constexpr VkFormat kKnown[] = {
        VK_FORMAT_R16G16B16A16_SFLOAT,     VK_FORMAT_R32G32B32A32_SFLOAT,
        VK_FORMAT_B10G11R11_UFLOAT_PACK32, VK_FORMAT_A2B10G10R10_UNORM_PACK32,
        VK_FORMAT_R8G8B8A8_UNORM,          VK_FORMAT_R8G8B8A8_SRGB,
        VK_FORMAT_B8G8R8A8_UNORM,          VK_FORMAT_B8G8R8A8_SRGB};
    std::vector<std::string> names;
    for (VkFormat f : kKnown) {
        names.push_back(rg::formatName(f));
        if (names.back() == name) return f;
    }
    throw std::runtime_error("--color " + name + ": not a color format budget knows (" +
                             joined(names) + ")");
}

// --lights: a comma-separated list of lights, each TYPE[:shadowed|:unshadowed][:METHOD], TYPE one
// of sun (or directional), spot and point.
struct LightList {
    std::vector<lightscatter::BudgetLight> lights;
    bool perLight = false;  // some light says whether it is shadowed, or its method
    std::string preset;     // a method's preset some light names ("froxels-unreal"), if any
};

// A method's name, or a preset's (MethodInfo::presets), which names its method too: sets `method`,
// and `preset` to the preset's name.
bool methodOrPreset(const std::string& name, std::string& preset, lightscatter::Method& method) {
    if (const auto m = lightscatter::parseMethod(name)) {
        method = *m;
        return true;
    }
    lightscatter::Settings scratch;
    const auto m = lightscatter::applyMethodPreset(name, scratch);
    if (!m) return false;
    method = *m;
    preset = name;
    return true;
}

LightList parseLights(const std::string& list) {
    LightList out;
    const std::string quoted = echoText(list);
    size_t start = 0;
    while (true) {
        const size_t comma = list.find(',', start);
        const std::string entry =
            list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        std::vector<std::string> parts;
        for (size_t at = 0;;) {
            const size_t colon = entry.find(':', at);
            parts.push_back(entry.substr(at, colon == std::string::npos ? colon : colon - at));
            if (colon == std::string::npos) break;
            at = colon + 1;
        }
        lightscatter::BudgetLight l;
        const std::string& name = parts[0];
        if (name == "sun" || name == "directional")
            l.type = lightscatter::LightType::Directional;
        else if (name == "spot")
            l.type = lightscatter::LightType::Spot;
        else if (name == "point")
            l.type = lightscatter::LightType::Point;
        else
            throw std::runtime_error(
                "--lights " + quoted + ": unknown light '" + echoText(name) +
                "' (a comma-separated list of sun, directional, spot and "
                "point, each optionally :shadowed or :unshadowed and :METHOD)");
        bool shadowGiven = false, methodGiven = false;
        for (size_t k = 1; k < parts.size(); ++k) {
            const std::string& m = parts[k];
            if ((m == "shadowed" || m == "unshadowed") && !shadowGiven) {
                l.shadowed = m == "shadowed";
                shadowGiven = true;
            } else if (std::string preset; !methodGiven && methodOrPreset(m, preset, l.method)) {
                methodGiven = true;
                // A preset sets the frame's settings, which all its lights share.
                if (!preset.empty() && !out.preset.empty() && out.preset != preset)
                    throw std::runtime_error("--lights " + quoted + ": presets '" + out.preset +
                                             "' and '" + preset +
                                             "': one frame's lights share one set of settings, "
                                             "so one preset");
                if (!preset.empty()) out.preset = preset;
            } else {
                throw std::runtime_error("--lights " + quoted + ": '" + echoText(entry) + "': '" +
                                         echoText(m) +
                                         "' is not shadowed, unshadowed or a method's or a "
                                         "preset's name (each at most once)");
            }
        }
        out.perLight = out.perLight || parts.size() > 1;
        out.lights.push_back(l);
        if (comma == std::string::npos) return out;
        start = comma + 1;
    }
}

std::string lightsName(const std::vector<lightscatter::BudgetLight>& lights,
                       const std::vector<std::string>& methods, bool perLight) {
    std::string s;
    for (size_t i = 0; i < lights.size(); ++i) {
        const auto l = lights[i].type;
        s += std::string(s.empty() ? "" : ",") + (l == lightscatter::LightType::Directional ? "sun"
                                                  : l == lightscatter::LightType::Spot      ? "spot"
                                                                                       : "point");
        if (perLight)
            s += std::string(lights[i].shadowed ? ":shadowed:" : ":unshadowed:") +
                 (i < methods.size() ? methods[i] : "auto");
    }
    return s;
}

}  // namespace

int runBudget(Args& args) {
    const std::string methodName = args.take("--method", "");
    const std::string settingsPath = args.take("--settings", "");
    const std::string profileName =
        args.take("--profile", settingsPath.empty() ? "all" : "balanced");
    const VkExtent2D size = parseSize(args.take("--size", "2560x1600"), "--size");
    const std::string sm = args.take("--shadow-map", "");
    const LightList lightList = parseLights(args.take("--lights", "spot"));
    const VkFormat color = parseColorFormat(args.take("--color", "R16G16B16A16_SFLOAT"));
    const bool json = args.flag("--json");
    args.finish();
    std::vector<lightscatter::Profile> profiles;
    lightscatter::Settings custom;
    if (profileName == "all") {
        if (!settingsPath.empty())
            throw std::runtime_error(
                "--settings overlays one profile: give --profile NAME, not all");
        for (const std::string& n : lightscatter::profileNames())
            if (n != "custom") profiles.push_back(*lightscatter::parseProfile(n));
    } else if (!lightscatter::parseProfile(profileName)) {
        std::string known = "all";
        for (const auto& n : lightscatter::profileNames()) known += ", " + n;
        throw std::runtime_error("unknown profile '" + profileName + "' (known: " + known + ")");
    } else {
        const RenderOptions chosen = profileOptions(profileName, settingsPath);
        profiles = {chosen.profile};
        custom = chosen.custom;
    }
    // A preset's settings go over --settings'.
    const lightscatter::Method method =
        budgetMethod(methodName.empty() ? "epipolar" : methodName, custom);
    // A light's preset goes over --method's, as over --settings'.
    if (!lightList.preset.empty()) (void)lightscatter::applyMethodPreset(lightList.preset, custom);
    // A light that says whether it is shadowed or its method budgets the set light by light:
    // each light's method its own, else --method where given, else auto. A light of the plain
    // list has a shadow map where the method samples one.
    std::vector<lightscatter::BudgetLight> set = lightList.lights;
    const lightscatter::MethodInfo& info = lightscatter::methodInfo()[static_cast<size_t>(method)];
    for (auto& l : set) {
        if (!lightList.perLight) {
            l.method = method;
            l.shadowed =
                l.type == lightscatter::LightType::Point ? info.cubeShadow : info.shadowMap;
        } else if (l.method == lightscatter::Method::Auto && !methodName.empty()) {
            l.method = method;
        }
    }
    const uint32_t shadowOverride = sm.empty() ? 0 : parseWhole(sm, "--shadow-map", 1, 16384);

    nlohmann::json all = nlohmann::json::array();
    for (lightscatter::Profile p : profiles) {
        const lightscatter::Settings s = lightscatter::profileSettings(p, custom);
        const uint32_t shadow = shadowOverride ? shadowOverride : s.shadowMapSize;
        const lightscatter::Budget b =
            lightscatter::budget(p, size.width, size.height, shadow, set, &custom, color);
        const std::string lightsText = lightsName(set, b.lightMethods, lightList.perLight);
        if (json) {
            nlohmann::json j;
            j["method"] = lightscatter::methodName(method);
            j["profile"] = lightscatter::profileName(p);
            j["screen"] = {size.width, size.height};
            j["settings"] = nlohmann::json::object();
            for (const SettingField* f : shownFields(method))
                j["settings"][f->name] = fieldJson(s, *f);
            j["shadowMapSize"] = shadow;
            j["colorFormat"] = rg::formatName(color);
            j["lights"] = lightsText;
            j["lightMethods"] = b.lightMethods;
            j["estimated"] = b.estimated;
            j["depthStencilFormat"] = b.depthStencilFormat;
            nlohmann::json entries = nlohmann::json::array();
            for (const auto& e : b.entries)
                entries.push_back({{"name", e.name},
                                   {"format", e.format},
                                   {"width", e.width},
                                   {"height", e.height},
                                   {"depth", e.depth},
                                   {"bytes", e.bytes},
                                   {"transient", e.transient}});
            j["resources"] = entries;
            j["totalBytes"] = b.totalBytes;
            j["peakBytes"] = b.peakBytes;
            if (b.seed)
                j["seed"] = {{"screen", {b.seed->screenWidth, b.seed->screenHeight}},
                             {"megabytes", b.seed->megabytes},
                             {"milliseconds", b.seed->milliseconds}};
            all.push_back(j);
            continue;
        }
        std::string what;
        for (const SettingField* f : shownFields(method)) {
            const nlohmann::json v = fieldJson(s, *f);
            what += (what.empty() ? "" : ", ") + f->name + " " +
                    (v.is_string() ? v.get<std::string>() : v.dump());
        }
        std::printf("%s, %s: %s%s%u^2 shadow map, %ux%u screen, light%s %s (sizes %s)\n",
                    lightList.perLight ? "a method per light" : lightscatter::methodName(method),
                    lightscatter::profileName(p), what.c_str(), what.empty() ? "" : ", ", shadow,
                    size.width, size.height, set.size() > 1 ? "s" : "", lightsText.c_str(),
                    b.estimated ? "estimated without a device" : "from the device");
        for (const auto& e : b.entries)
            std::printf("  %-40s %-22s %5u x %-5u%s %10.2f MiB%s\n", e.name.c_str(),
                        e.format.c_str(), e.width, e.height,
                        e.depth > 1 ? (" x " + std::to_string(e.depth)).c_str() : "", mib(e.bytes),
                        e.transient ? "" : "  (kept across frames)");
        std::printf("  total without aliasing %.1f MiB, peak with aliasing %.1f MiB",
                    mib(b.totalBytes), mib(b.peakBytes));
        if (b.seed)
            std::printf("; seed 000: %.1f MB at %ux%u", b.seed->megabytes, b.seed->screenWidth,
                        b.seed->screenHeight);
        std::printf("\n\n");
    }
    if (json) std::cout << all.dump(2) << "\n";
    return 0;
}

}  // namespace host
