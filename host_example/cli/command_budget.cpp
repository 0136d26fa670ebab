// lightscatter budget [--method epipolar|planes|beam-tree-analytic|beam-tree-sampling|froxels]
// [--profile NAME|all] [--settings FILE.json]
//   [--size WxH] [--shadow-map N] [--lights sun,spot:unshadowed,point:brute-force,...] [--json]
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "command_options.h"
#include "commands.h"
#include "settings_file.h"

namespace host {
namespace {

double mib(uint64_t bytes) {
    return static_cast<double>(bytes) / (1024.0 * 1024.0);
}

// The methods whose textures depend on the profile or the grid, the ones lightscatter::budget
// knows; a froxel preset sets its grid in `settings`.
lightscatter::Method budgetMethod(const std::string& name, lightscatter::Settings& settings) {
    if (lightscatter::applyFroxelPreset(name, settings)) return lightscatter::Method::Froxels;
    const auto m = lightscatter::parseMethod(name);
    if (m == lightscatter::Method::Epipolar || m == lightscatter::Method::Planes ||
        m == lightscatter::Method::BeamTreeAnalytic ||
        m == lightscatter::Method::BeamTreeSampling || m == lightscatter::Method::Froxels)
        return *m;
    const char* known =
        "epipolar, planes, beam-tree-analytic, beam-tree-sampling, froxels (froxels-hdrp, "
        "froxels-unreal)";
    if (!m) throw std::runtime_error("unknown method '" + name + "' (budget knows: " + known + ")");
    throw std::runtime_error("--method " + name + ": budget knows " + known +
                             " only, the methods whose textures depend on the profile or grid");
}

// --lights: a comma-separated list of lights, each TYPE[:shadowed|:unshadowed][:METHOD], TYPE one
// of sun (or directional), spot and point.
struct LightList {
    std::vector<lightscatter::BudgetLight> lights;
    bool perLight = false;  // some light says whether it is shadowed, or its method
};

LightList parseLights(const std::string& list) {
    LightList out;
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
                "--lights " + list + ": unknown light '" + name +
                "' (a comma-separated list of sun, directional, spot and "
                "point, each optionally :shadowed or :unshadowed and :METHOD)");
        bool shadowGiven = false, methodGiven = false;
        for (size_t k = 1; k < parts.size(); ++k) {
            const std::string& m = parts[k];
            if ((m == "shadowed" || m == "unshadowed") && !shadowGiven) {
                l.shadowed = m == "shadowed";
                shadowGiven = true;
            } else if (const auto method = lightscatter::parseMethod(m); method && !methodGiven) {
                l.method = *method;
                methodGiven = true;
            } else {
                throw std::runtime_error("--lights " + list + ": '" + entry + "': '" + m +
                                         "' is not shadowed, unshadowed or a method name (each "
                                         "at most once)");
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
    lightscatter::Settings preset;  // a froxel preset's grid
    const bool froxelPreset = lightscatter::applyFroxelPreset(methodName, preset);
    const lightscatter::Method method =
        budgetMethod(methodName.empty() ? "epipolar" : methodName, preset);
    const bool froxels = method == lightscatter::Method::Froxels;
    // planes and the beam trees sample with planes
    const bool planes = method != lightscatter::Method::Epipolar && !froxels;
    const std::string settingsPath = args.take("--settings", "");
    const std::string profileName =
        args.take("--profile", settingsPath.empty() ? "all" : "balanced");
    const VkExtent2D size = parseSize(args.take("--size", "2560x1600"), "--size");
    const std::string sm = args.take("--shadow-map", "");
    const LightList lightList = parseLights(args.take("--lights", "spot"));
    // A light that says whether it is shadowed or its method budgets the set light by light:
    // each light's method its own, else --method where given, else auto.
    std::vector<lightscatter::BudgetLight> set = lightList.lights;
    std::vector<lightscatter::LightType> lights;
    for (auto& l : set) {
        lights.push_back(l.type);
        if (l.method == lightscatter::Method::Auto && !methodName.empty()) l.method = method;
    }
    const bool json = args.flag("--json");
    args.finish();
    std::vector<lightscatter::Profile> profiles;
    lightscatter::Settings custom;
    if (profileName == "all") {
        if (!settingsPath.empty())
            throw std::runtime_error(
                "--settings overlays one profile: give --profile NAME, not all");
        profiles = {
            lightscatter::Profile::HighQuality,     lightscatter::Profile::Balanced,
            lightscatter::Profile::HighPerformance, lightscatter::Profile::LowHighQuality,
            lightscatter::Profile::LowBalanced,     lightscatter::Profile::LowHighPerformance};
    } else if (!lightscatter::parseProfile(profileName)) {
        std::string known = "all";
        for (const auto& n : lightscatter::profileNames()) known += ", " + n;
        throw std::runtime_error("unknown profile '" + profileName + "' (known: " + known + ")");
    } else {
        const RenderOptions chosen = profileOptions(profileName, settingsPath);
        profiles = {chosen.profile};
        custom = chosen.custom;
    }
    const uint32_t shadowOverride = sm.empty() ? 0 : parseWhole(sm, "--shadow-map", 1, 16384);

    nlohmann::json all = nlohmann::json::array();
    for (lightscatter::Profile p : profiles) {
        auto s = p == lightscatter::Profile::Custom ? custom : lightscatter::profileSettings(p);
        if (froxelPreset) {
            s.froxelTile = preset.froxelTile;
            s.froxelSlices = preset.froxelSlices;
            s.froxelTemporal = preset.froxelTemporal;
        } else if (p != lightscatter::Profile::Custom) {
            s.froxelTile = custom.froxelTile;  // the grid is read from --settings with any profile
            s.froxelSlices = custom.froxelSlices;
            s.froxelFarDistance = custom.froxelFarDistance;
            s.froxelTemporal = custom.froxelTemporal;
        }
        const uint32_t shadow = shadowOverride ? shadowOverride : s.shadowMapSize;
        const lightscatter::Budget b =
            lightList.perLight
                ? lightscatter::budget(p, size.width, size.height, shadow, set, &s)
                : lightscatter::budget(p, size.width, size.height, shadow, lights, &s, method);
        const std::string lightsText = lightsName(set, b.lightMethods, lightList.perLight);
        if (json) {
            nlohmann::json j;
            j["method"] = lightscatter::methodName(method);
            j["profile"] = lightscatter::profileName(p);
            j["screen"] = {size.width, size.height};
            if (froxels) {
                j["froxelTile"] = s.froxelTile;
                j["froxelSlices"] = s.froxelSlices;
            } else if (planes) {
                j["planeCount"] = s.planeCount;
                j["planeTarget"] = planeTargetName(s.planeTarget);
                j["planeBlur"] = s.planeBlur;
            } else {
                j["slices"] = s.slices;
                j["samplesPerSlice"] = s.samplesPerSlice;
            }
            j["shadowMapSize"] = shadow;
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
            if (b.seed &&
                method == lightscatter::Method::Epipolar)  // seed 000's figures are epipolar's
                j["seed"] = {{"screen", {b.seed->screenWidth, b.seed->screenHeight}},
                             {"megabytes", b.seed->megabytes},
                             {"milliseconds", b.seed->milliseconds}};
            all.push_back(j);
            continue;
        }
        const std::string what =
            froxels
                ? "froxel columns of " + std::to_string(s.froxelTile) + "x" +
                      std::to_string(s.froxelTile) + " pixels, " + std::to_string(s.froxelSlices) +
                      " depth slices" + (s.froxelTemporal ? ", temporal" : "")
            : method == lightscatter::Method::BeamTreeAnalytic
                ? std::to_string(s.planeCount) + " sampling planes where uncertain, float32 target"
            : method == lightscatter::Method::BeamTreeSampling
                ? std::to_string(s.planeCount) +
                      " sampling planes where lit or uncertain, float32 target"
            : planes
                ? std::to_string(s.planeCount) + " planes into " + planeTargetName(s.planeTarget) +
                      (s.planeBlur ? ", blur " + std::to_string(s.planeBlur) : "")
                : std::to_string(s.slices) + " slices x " + std::to_string(s.samplesPerSlice) +
                      " samples";
        std::printf("%s, %s: %s, %u^2 shadow map, %ux%u screen, light%s %s (sizes %s)\n",
                    lightList.perLight ? "a method per light" : lightscatter::methodName(method),
                    lightscatter::profileName(p), what.c_str(), shadow, size.width, size.height,
                    lights.size() > 1 ? "s" : "", lightsText.c_str(),
                    b.estimated ? "estimated without a device" : "from the device");
        for (const auto& e : b.entries)
            std::printf("  %-40s %-22s %5u x %-5u%s %10.2f MiB%s\n", e.name.c_str(),
                        e.format.c_str(), e.width, e.height,
                        e.depth > 1 ? (" x " + std::to_string(e.depth)).c_str() : "", mib(e.bytes),
                        e.transient ? "" : "  (kept across frames)");
        std::printf("  total without aliasing %.1f MiB, peak with aliasing %.1f MiB",
                    mib(b.totalBytes), mib(b.peakBytes));
        if (b.seed && method == lightscatter::Method::Epipolar)
            std::printf("; seed 000: %.1f MB at %ux%u", b.seed->megabytes, b.seed->screenWidth,
                        b.seed->screenHeight);
        std::printf("\n\n");
    }
    if (json) std::cout << all.dump(2) << "\n";
    return 0;
}

}  // namespace host
