#include "bench_config.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "cli_args.h"
#include "scene/input_file.h"
#include "scene/json_input.h"

namespace host::bench {
namespace {

// A method as a configuration names it: a froxel preset is froxels with its grid in `settings`.
struct MethodName {
    lightscatter::Method method;
    std::string name;
    lightscatter::Settings settings;
};

using nlohmann::json;

// A sweep's run of a method: its enum value and a preset's froxel grid over the sweep's settings.
void useMethod(BenchRun& r, const MethodName& m) {
    r.method = m.method;
    r.settings.froxelTile = m.settings.froxelTile;
    r.settings.froxelSlices = m.settings.froxelSlices;
    r.settings.froxelTemporal = m.settings.froxelTemporal;
}

constexpr uint64_t kConfigFileCap = 1 * kMiB;
// A configuration's runs are its scenes times its methods, profiles and sweep values: they grow as
// the square of the file (1000 scenes and 1000 sweep values are 30 KB and a million runs, each
// checked with the plugin's budget). The largest shipped one, bench/full.json, has 420.
constexpr size_t kMaxRuns = 10000;

// The planes method's sweeps were named after "slice" until the word came to mean only an
// epipolar line; configurations written with those names still read.
constexpr std::pair<const char*, const char*> kFormerSweepKeys[] = {
    {"slicePlanes", "planeCount"}, {"sliceTargets", "planeTargets"}};

// The sweep a key of `sweeps` names: itself, or the sweep of its former name.
std::string currentSweepKey(const std::string& key) {
    for (const auto& [former, current] : kFormerSweepKeys)
        if (key == former) return current;
    return key;
}

// Reads one configuration; every failure names the file and the field. Every run it expands to
// is checked here, before the benchmark renders anything, so a bad sweep value at the end of a
// long configuration is found at once rather than hours in.
class ConfigReader {
  public:
    ConfigReader(const std::string& path, const std::string& projectRoot)
        : path_(path), root_(projectRoot) {}

    BenchConfig read() const {
        const json j = parse();
        if (!j.is_object()) fail("the top level must be a JSON object");
        for (const auto& [key, value] : j.items())
            if (key != "name" && key != "frames" && key != "warmup" && key != "size" &&
                key != "scenes" && key != "methods" && key != "profiles" && key != "sweeps" &&
                key != "measureError" && key != "motion" && key != "sweepProfile" &&
                key != "profileShadowMap" && key != "configurations")
                fail("unknown key '" + echoText(key) +
                     "' (known: name, frames, warmup, size, scenes, methods, profiles, sweeps, "
                     "sweepProfile, measureError, motion, profileShadowMap, configurations)");
        BenchConfig c;
        c.name = j.contains("name") ? text(j["name"], "name")
                                    : std::filesystem::path(path_).stem().string();
        c.frames = int(whole(j, "frames", 10, 1, 10000));
        c.warmup = int(whole(j, "warmup", 3, 0, 10000));
        c.size = size(j.contains("size") ? j["size"] : json("480x270"), "size");
        if (j.contains("measureError")) {
            if (!j["measureError"].is_boolean())
                fail("measureError = " + echo(j["measureError"]) + ": must be true or false");
            c.measureError = j["measureError"].get<bool>();
        }
        bool profileShadowMap = false;
        if (j.contains("profileShadowMap")) {
            if (!j["profileShadowMap"].is_boolean())
                fail("profileShadowMap = " + echo(j["profileShadowMap"]) +
                     ": must be true or false");
            profileShadowMap = j["profileShadowMap"].get<bool>();
        }
        if (j.contains("motion")) {
            c.motion = motion(j["motion"]);
            if (!c.measureError)
                fail(
                    "motion needs measureError: the flicker is measured against the float64 "
                    "reference at every pose");
        }
        if (!j.contains("scenes")) fail("scenes is required");
        std::vector<lightscatter::Profile> profiles;
        for (const json& p :
             list(j.contains("profiles") ? j["profiles"] : json::array({"balanced"}), "profiles")) {
            const std::string name = text(p, "profiles[]");
            const auto parsed = lightscatter::parseProfile(name);
            if (!parsed || *parsed == lightscatter::Profile::Custom)
                fail("profiles: unknown profile '" + echoText(name) + "'");
            profiles.push_back(*parsed);
        }
        if (profiles.empty())
            fail("profiles is empty: list at least one profile, or leave the key out for balanced");
        // With configurations, the methods' list may be empty: they are the runs.
        const bool onlyConfigured = j.contains("configurations") && j.contains("methods") &&
                                    j["methods"].is_array() && j["methods"].empty();
        const std::vector<MethodName> methods =
            onlyConfigured
                ? std::vector<MethodName>{}
                : methodList(j.contains("methods") ? j["methods"]
                                                   : json::array({"epipolar", "brute-force"}),
                             "methods");
        // A scene is its file's path, or {"scene": path, "methods": [...]} with methods of its
        // own: those that take its lights (a cube shadow map or several lights are not every
        // method's).
        std::vector<std::vector<MethodName>> sceneMethods;
        const json scenes = list(j["scenes"], "scenes");
        for (size_t k = 0; k < scenes.size(); ++k) {
            const json& s = scenes[k];
            const std::string where = "scenes[" + std::to_string(k) + "]";
            std::filesystem::path p;
            sceneMethods.push_back(methods);
            if (s.is_object()) {
                for (const auto& [key, value] : s.items())
                    if (key != "scene" && key != "methods")
                        fail(where + ": unknown key '" + echoText(key) +
                             "' (known: scene, methods)");
                if (!s.contains("scene")) fail(where + ".scene is required");
                p = text(s["scene"], where + ".scene");
                if (s.contains("methods"))
                    sceneMethods.back() = methodList(s["methods"], where + ".methods");
            } else if (s.is_string()) {
                p = s.get<std::string>();
            } else {
                fail(where +
                     " must be a scene file's path or an object {\"scene\": path, \"methods\": "
                     "[...]}");
            }
            if (p.empty() || p.native().size() > kMaxPathChars ||
                p.native().find('\0') != std::string::npos)
                fail(where + " = " + echo(s.is_object() ? s["scene"] : s) +
                     ": must be a path (not empty, no NUL character, at most " +
                     std::to_string(kMaxPathChars) + " bytes)");
            if (p.is_relative()) p = std::filesystem::path(root_) / p;
            c.scenes.push_back(p.string());
        }
        if (c.scenes.empty()) fail("scenes is empty");
        lightscatter::Profile sweepProfile = lightscatter::Profile::Balanced;
        if (j.contains("sweepProfile")) {
            const std::string name = text(j["sweepProfile"], "sweepProfile");
            const auto parsed = lightscatter::parseProfile(name);
            if (!parsed || *parsed == lightscatter::Profile::Custom)
                fail("sweepProfile: unknown profile '" + echoText(name) + "'");
            sweepProfile = *parsed;
        }
        const json sweeps = j.contains("sweeps") ? j["sweeps"] : json::object();
        if (!sweeps.is_object()) fail("sweeps must be an object");
        for (const auto& [key, value] : sweeps.items()) {
            const std::string k = currentSweepKey(key);
            if (k != "slices" && k != "samples" && k != "initialStep" && k != "shadowMapSize" &&
                k != "size" && k != "minMaxTrees" && k != "coneSamples" && k != "coneModes" &&
                k != "planeCount" && k != "planeTargets" && k != "lightModel" &&
                k != "refinementThreshold" && k != "inscatterRefinementThreshold")
                fail("sweeps: unknown key '" + echoText(key) +
                     "' (known: slices, samples, initialStep, refinementThreshold, "
                     "inscatterRefinementThreshold, shadowMapSize, "
                     "size, minMaxTrees, coneSamples, coneModes, planeCount, planeTargets, "
                     "lightModel)");
            if (k != key && sweeps.contains(k))
                fail("sweeps." + key + " and sweeps." + k + " are one sweep (" + key +
                     " is its former name): give it once");
        }
        const std::vector<BenchRun> configured = j.contains("configurations")
                                                     ? configurations(j["configurations"])
                                                     : std::vector<BenchRun>{};
        for (size_t k = 0; k < c.scenes.size(); ++k) {
            expand(c, c.scenes[k], sceneMethods[k], profiles, sweepProfile, sweeps);
            for (BenchRun r : configured) {
                r.scene = c.scenes[k];
                if (r.size.width == 0) r.size = c.size;
                r.measureError = c.measureError && r.size.width == c.size.width &&
                                 r.size.height == c.size.height;
                add(c, r);
            }
        }
        if (profileShadowMap) applyProfileShadowMaps(c, profiles);
        return c;
    }

  private:
    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error(path_ + ": " + what);
    }

    json parse() const {
        try {
            return readJsonFile(path_, "benchmark configuration", kConfigFileCap);
        } catch (const JsonInputError& e) {
            throw std::runtime_error(e.what());
        }
    }

    std::string text(const json& v, const std::string& name) const {
        if (!v.is_string()) fail(name + " must be a string");
        return v.get<std::string>();
    }

    std::vector<MethodName> methodList(const json& v, const std::string& name) const {
        std::vector<MethodName> methods;
        for (const json& m : list(v, name)) {
            const std::string method = text(m, name + "[]");
            MethodName n{lightscatter::Method::Froxels, method, {}};
            if (lightscatter::applyFroxelPreset(method, n.settings)) {
                methods.push_back(n);
                continue;
            }
            const auto parsed = lightscatter::parseMethod(method);
            if (!parsed) {
                std::string known;
                for (const auto& k : lightscatter::methodNames())
                    known += (known.empty() ? "" : ", ") + k;
                for (const auto& p : lightscatter::froxelPresets())
                    known += std::string(", ") + p.name;
                fail(name + ": unknown method '" + echoText(method) + "' (known: " + known + ")");
            }
            methods.push_back({*parsed, lightscatter::methodName(*parsed), {}});
        }
        if (methods.empty())
            fail(name +
                 " is empty: list at least one method, or leave the key out for the default list");
        return methods;
    }

    // By value: callers pass temporaries (a default list) and iterate over the result.
    json list(const json& v, const std::string& name) const {
        if (!v.is_array()) fail(name + " must be an array");
        return v;
    }

    // A whole number in [lo, hi]: nlohmann's get<int> would wrap 4294967297 around to 1.
    uint32_t whole(const json& v, const std::string& name, uint32_t lo, uint32_t hi) const {
        const bool negative =
            v.is_number_integer() && !v.is_number_unsigned() && v.get<int64_t>() < 0;
        if (!v.is_number_integer() || negative || v.get<uint64_t>() < lo || v.get<uint64_t>() > hi)
            fail(name + " = " + echo(v) + ": must be a whole number from " + std::to_string(lo) +
                 " to " + std::to_string(hi));
        return uint32_t(v.get<uint64_t>());
    }

    uint32_t whole(const json& object, const char* key, uint32_t fallback, uint32_t lo,
                   uint32_t hi) const {
        return object.contains(key) ? whole(object[key], key, lo, hi) : fallback;
    }

    static std::string shortNumber(double x) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", x);
        return buf;
    }

    // A finite number from lo to hi.
    double number(const json& object, const char* key, double fallback, double lo,
                  double hi) const {
        if (!object.contains(key)) return fallback;
        const json& v = object[key];
        const std::string name = std::string("motion.") + key;
        if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < lo ||
            v.get<double>() > hi)
            fail(name + " = " + echo(v) + ": must be a number from " + shortNumber(lo) + " to " +
                 shortNumber(hi));
        return v.get<double>();
    }

    Motion motion(const json& v) const {
        const char* known =
            "what, frames, lightDegreesPerFrame, lightMetresPerFrame, cameraMetresPerFrame, "
            "cameraDegreesPerFrame";
        if (!v.is_object()) fail(std::string("motion must be an object (keys: ") + known + ")");
        for (const auto& [key, value] : v.items())
            if (key != "what" && key != "frames" && key != "lightDegreesPerFrame" &&
                key != "lightMetresPerFrame" && key != "cameraMetresPerFrame" &&
                key != "cameraDegreesPerFrame")
                fail("motion: unknown key '" + echoText(key) + "' (known: " + known + ")");
        if (!v.contains("what"))
            fail("motion.what is required: \"light\", \"camera\" or both in an array");
        Motion m;
        const json what = v["what"].is_string() ? json::array({v["what"]}) : v["what"];
        if (!what.is_array() || what.empty())
            fail("motion.what = " + echo(v["what"]) +
                 ": must be \"light\", \"camera\" or a non-empty array of them");
        for (const json& w : what) {
            if (w != "light" && w != "camera")
                fail("motion.what[] = " + echo(w) + ": must be \"light\" or \"camera\"");
            const MotionKind kind = w == "light" ? MotionKind::Light : MotionKind::Camera;
            if (std::find(m.what.begin(), m.what.end(), kind) != m.what.end())
                fail("motion.what lists " + echo(w) + " twice");
            m.what.push_back(kind);
        }
        // Two frames make the first pair; the flicker is a change from one frame to the next.
        if (v.contains("frames")) m.frames = int(whole(v["frames"], "motion.frames", 2, 10000));
        m.lightDegreesPerFrame = number(v, "lightDegreesPerFrame", m.lightDegreesPerFrame, 0, 10);
        m.lightMetresPerFrame = number(v, "lightMetresPerFrame", m.lightMetresPerFrame, 0, 10);
        m.cameraMetresPerFrame = number(v, "cameraMetresPerFrame", m.cameraMetresPerFrame, 0, 10);
        m.cameraDegreesPerFrame =
            number(v, "cameraDegreesPerFrame", m.cameraDegreesPerFrame, 0, 10);
        return m;
    }

    // parseSize's message quotes the text as it is; a configuration's text is echoed (a "\n" in
    // it made a two-line error; found by bench_fuzzer).
    VkExtent2D size(const json& v, const std::string& name) const {
        const std::string given = text(v, name);
        try {
            return parseSize(given, name);
        } catch (const std::runtime_error&) {
            fail(name + " '" + echoText(given) +
                 "' is not WIDTHxHEIGHT with both whole numbers from 1 to 16384");
        }
    }

    // Every run is added here, and the configuration refused as soon as it has too many, before
    // millions of them take memory and time.
    void add(BenchConfig& c, const BenchRun& r) const {
        if (c.runs.size() >= kMaxRuns)
            fail("expands to more than " + std::to_string(kMaxRuns) +
                 " runs (scenes x methods, profiles and sweep values): split it into several "
                 "configurations");
        c.runs.push_back(r);
    }

    // The plugin's rules for settings, applied without a GPU through its budget.
    void checkSettings(const BenchRun& r, const std::string& where) const {
        try {
            (void)lightscatter::budget(lightscatter::Profile::Custom, 64, 64, 64,
                                       lightscatter::LightType::Spot, &r.settings);
        } catch (const lightscatter::InvalidInput& e) {
            std::string why = e.what();
            for (const char* prefix : {"lightscatter: ", "custom."})
                if (why.rfind(prefix, 0) == 0) why.erase(0, std::char_traits<char>::length(prefix));
            fail(where + " (run '" + r.label + "'): " + why);
        }
    }

    // "configurations": named runs of settings no profile or one-parameter sweep gives (seed 000's
    // smaller GPUs' profiles, seed 003's modes at its sample counts): each an object with a
    // "label", a "method" (default epipolar; a froxel preset too), the profile it starts "from"
    // (default balanced) and any of the keys below. Checked by the plugin's rules like a sweep.
    std::vector<BenchRun> configurations(const json& v) const {
        std::vector<BenchRun> runs;
        const json items = list(v, "configurations");
        if (items.empty()) fail("configurations is empty: leave the key out, or list a run");
        for (size_t i = 0; i < items.size(); ++i) {
            const json& o = items[i];
            const std::string at = "configurations[" + std::to_string(i) + "]";
            if (!o.is_object()) fail(at + " must be an object");
            static const char* const kKeys[] = {
                "label",       "method",      "from",          "slices",       "samples",
                "initialStep", "minMaxTrees", "shadowMapSize", "coneSamples",  "coneMode",
                "planeCount",  "planeBlur",   "planeTarget",   "planeSpacing", "sizes"};
            for (const auto& item : o.items()) {
                const std::string& key = item.key();
                if (std::find_if(std::begin(kKeys), std::end(kKeys),
                                 [&key](const char* k) { return key == k; }) == std::end(kKeys))
                    fail(at + ": unknown key '" + echoText(key) +
                         "' (known: label, method, from, slices, samples, initialStep, "
                         "minMaxTrees, shadowMapSize, coneSamples, coneMode, planeCount, "
                         "planeBlur, planeTarget, planeSpacing, sizes)");
            }
            if (!o.contains("label")) fail(at + ".label is required");
            BenchRun r;
            r.family = "configurations";
            r.label = text(o["label"], at + ".label");
            for (const BenchRun& earlier : runs)
                if (earlier.label == r.label)
                    fail(at + ".label '" + echoText(r.label) + "' names an earlier run too");
            lightscatter::Profile from = lightscatter::Profile::Balanced;
            if (o.contains("from")) {
                const std::string name = text(o["from"], at + ".from");
                const auto parsed = lightscatter::parseProfile(name);
                if (!parsed || *parsed == lightscatter::Profile::Custom)
                    fail(at + ".from: unknown profile '" + echoText(name) + "'");
                from = *parsed;
            }
            r.custom = true;
            r.settings = lightscatter::profileSettings(from);
            if (o.contains("method"))
                useMethod(r, methodList(json::array({o["method"]}), at + ".method").front());
            using Settings = lightscatter::Settings;
            auto wholeKey = [&](const char* key, uint32_t Settings::*field, uint32_t lo,
                                uint32_t hi) {
                if (o.contains(key)) r.settings.*field = whole(o[key], at + "." + key, lo, hi);
            };
            wholeKey("slices", &Settings::slices, 0, std::numeric_limits<uint32_t>::max());
            wholeKey("samples", &Settings::samplesPerSlice, 0,
                     std::numeric_limits<uint32_t>::max());
            wholeKey("initialStep", &Settings::initialSampleStep, 0,
                     std::numeric_limits<uint32_t>::max());
            wholeKey("coneSamples", &Settings::coneSamples, 1, 4096);
            wholeKey("planeCount", &Settings::planeCount, 2, 4096);
            wholeKey("planeBlur", &Settings::planeBlur, 0, std::numeric_limits<uint32_t>::max());
            if (o.contains("minMaxTrees")) {
                if (!o["minMaxTrees"].is_boolean())
                    fail(at + ".minMaxTrees = " + echo(o["minMaxTrees"]) +
                         ": must be true or false");
                r.settings.minMaxTrees = o["minMaxTrees"].get<bool>();
            }
            if (o.contains("coneMode")) {
                const std::string m = text(o["coneMode"], at + ".coneMode");
                if (m != "cone" && m != "naive" && m != "no-shadow-sampling")
                    fail(at + ".coneMode = \"" + echoText(m) +
                         "\": must be cone, naive or no-shadow-sampling");
                r.settings.coneLimited = m != "naive";
                r.settings.shadowSampling = m != "no-shadow-sampling";
            }
            if (o.contains("planeSpacing")) {
                if (!o["planeSpacing"].is_number())
                    fail(at + ".planeSpacing = " + echo(o["planeSpacing"]) + ": must be a number");
                r.settings.planeSpacing = o["planeSpacing"].get<float>();
            }
            if (o.contains("planeTarget")) {
                const std::string t = text(o["planeTarget"], at + ".planeTarget");
                if (t != "float16" && t != "float32" && t != "rgba8" && t != "rgba8-dither")
                    fail(at + ".planeTarget = \"" + echoText(t) +
                         "\": must be float16, float32, rgba8 (the seed's rounding) or "
                         "rgba8-dither");
                r.settings.planeTarget = t == "float16" ? lightscatter::PlaneTarget::Float16
                                         : t == "float32"
                                             ? lightscatter::PlaneTarget::Float32
                                             : lightscatter::PlaneTarget::Rgba8Channels;
                r.settings.planeDither = t == "rgba8-dither";
            }
            if (o.contains("shadowMapSize"))
                r.shadowMapSize = whole(o["shadowMapSize"], at + ".shadowMapSize", 1, 16384);
            checkSettings(r, at);
            if (!o.contains("sizes")) {
                runs.push_back(r);
                continue;
            }
            // One run per screen size (seed 004 measures each setup at four), labelled with it;
            // errors only at the configuration's size, as a size sweep's.
            const json sizes = list(o["sizes"], at + ".sizes");
            if (sizes.empty()) fail(at + ".sizes is empty: leave the key out, or list a size");
            for (const json& given : sizes) {
                BenchRun sized = r;
                sized.size = size(given, at + ".sizes[]");
                sized.label = r.label + " " + given.get<std::string>();
                runs.push_back(sized);
            }
        }
        return runs;
    }

    // Each profile run's map is its profile's; every other run's the largest of the profiles'.
    static void applyProfileShadowMaps(BenchConfig& c,
                                       const std::vector<lightscatter::Profile>& profiles) {
        lightscatter::Profile largest = profiles.front();
        for (lightscatter::Profile p : profiles)
            if (lightscatter::profileSettings(p).shadowMapSize >
                lightscatter::profileSettings(largest).shadowMapSize)
                largest = p;
        for (BenchRun& r : c.runs) {
            if (r.shadowMapSize) continue;  // a shadow-map sweep sets its own
            const bool own = r.family == "profiles" && r.method == lightscatter::Method::Epipolar;
            const lightscatter::Profile p = own ? r.profile : largest;
            r.profileShadowMap = lightscatter::profileSettings(p).shadowMapSize;
            r.shadowMapFrom = std::string("profile ") + lightscatter::profileName(p);
        }
    }

    void expand(BenchConfig& c, const std::string& scene, const std::vector<MethodName>& methods,
                const std::vector<lightscatter::Profile>& profiles,
                lightscatter::Profile sweepProfile, const json& sweeps) const {
        BenchRun base;
        base.scene = scene;
        base.size = c.size;
        base.measureError = c.measureError;
        for (const MethodName& named : methods) {
            const lightscatter::Method m = named.method;
            // Only epipolar has the seed's profiles; the other methods run once, balanced (a
            // froxel preset with its grid).
            if (m != lightscatter::Method::Epipolar) {
                BenchRun r = base;
                r.method = m;
                r.family = "profiles";
                r.label = named.name;
                r.settings = named.settings;
                add(c, r);
                continue;
            }
            for (lightscatter::Profile p : profiles) {
                BenchRun r = base;
                r.method = m;
                r.profile = p;
                r.family = "profiles";
                r.label = std::string("epipolar ") + lightscatter::profileName(p);
                add(c, r);
            }
        }
        constexpr uint32_t kMax = std::numeric_limits<uint32_t>::max();
        // The key the file gave a sweep under: its name, or its former one.
        auto written = [&](const char* key) {
            for (const auto& [former, current] : kFormerSweepKeys)
                if (current == std::string(key) && sweeps.contains(former)) return former;
            return key;
        };
        auto named = [&](const char* key) { return std::string("sweeps.") + written(key); };
        auto values = [&](const char* key) {
            return sweeps.contains(written(key)) ? list(sweeps[written(key)], named(key))
                                                 : json::array();
        };
        // One-parameter sweeps from one profile (balanced unless sweepProfile says otherwise):
        // `read` checks each value of sweeps.<key> and calls emit(label, change) for each run it
        // makes; with `checked`, the plugin's rules check the run's settings.
        auto sweep = [&](const char* key, const char* family, bool checked, auto read) {
            for (const json& v : values(key))
                read(v, [&](const std::string& label, const auto& change) {
                    BenchRun r = base;
                    r.family = family;
                    r.label = label;
                    r.custom = true;
                    r.settings = lightscatter::profileSettings(sweepProfile);
                    change(r);
                    if (checked) checkSettings(r, named(key));
                    add(c, r);
                });
        };
        using Settings = lightscatter::Settings;
        auto wholeSetting = [&](const char* key, uint32_t Settings::*field) {
            sweep(key, key, true, [&](const json& v, auto emit) {
                const uint32_t n = whole(v, std::string("sweeps.") + key + "[]", 0, kMax);
                emit(std::string(key) + "=" + std::to_string(n),
                     [&](BenchRun& r) { r.settings.*field = n; });
            });
        };
        auto numberSetting = [&](const char* key, float Settings::*field) {
            sweep(key, key, true, [&](const json& v, auto emit) {
                if (!v.is_number())
                    fail(std::string("sweeps.") + key + "[] = " + echo(v) + ": must be a number");
                emit(std::string(key) + "=" + shortNumber(v.get<double>()),
                     [&](BenchRun& r) { r.settings.*field = v.get<float>(); });
            });
        };
        wholeSetting("slices", &Settings::slices);
        wholeSetting("samples", &Settings::samplesPerSlice);
        wholeSetting("initialStep", &Settings::initialSampleStep);
        // Epipolar's depth breaks: a smaller threshold marches more samples where the depth steps
        // a little (temporal stability: bench/flicker.json).
        numberSetting("refinementThreshold", &Settings::refinementThreshold);
        // Epipolar's refinement on in-scattering differences (0: off): the samples between two
        // marched ones that differ by more than this are marched too.
        numberSetting("inscatterRefinementThreshold", &Settings::inscatterRefinementThreshold);
        sweep("minMaxTrees", "trees", false, [&](const json& v, auto emit) {
            if (!v.is_boolean())
                fail("sweeps.minMaxTrees[] = " + echo(v) + ": must be true or false");
            emit(std::string("minMaxTrees=") + (v.get<bool>() ? "on" : "off"),
                 [&](BenchRun& r) { r.settings.minMaxTrees = v.get<bool>(); });
        });
        sweep("shadowMapSize", "shadowMapSize", false, [&](const json& v, auto emit) {
            const uint32_t n = whole(v, "sweeps.shadowMapSize[]", 1, 16384);
            for (const MethodName& m : methods)
                emit(m.name + " shadowMap=" + std::to_string(n), [&](BenchRun& r) {
                    useMethod(r, m);
                    r.shadowMapSize = n;
                });
        });
        // Seed 003's comparison: cone-march with each sample count and mode (the cone-limited
        // march, the naive full-ray march, the cone-limited march without shadow-map sampling).
        const json counts = values("coneSamples"), modes = values("coneModes");
        if (!modes.empty() && counts.empty()) fail("sweeps.coneModes needs sweeps.coneSamples");
        sweep("coneSamples", "cone", false, [&](const json& n, auto emit) {
            const uint32_t samples = whole(n, "sweeps.coneSamples[]", 1, 4096);
            for (const json& mode : modes.empty() ? json::array({"cone"}) : modes) {
                const std::string m = mode.is_string() ? mode.get<std::string>() : echo(mode);
                if (m != "cone" && m != "naive" && m != "no-shadow-sampling")
                    fail("sweeps.coneModes[] = " + echo(mode) +
                         ": must be cone, naive or no-shadow-sampling");
                emit(m + " " + std::to_string(samples), [&](BenchRun& r) {
                    r.method = lightscatter::Method::ConeMarch;
                    r.settings.coneSamples = samples;
                    r.settings.coneLimited = m != "naive";
                    r.settings.shadowSampling = m != "no-shadow-sampling";
                });
            }
        });
        // Seed 002: the planes method with each plane count and accumulation target.
        const json planes = values("planeCount"), targets = values("planeTargets");
        if (!targets.empty() && planes.empty())
            fail(named("planeTargets") + " needs sweeps.planeCount");
        sweep("planeCount", "planes", false, [&](const json& n, auto emit) {
            const uint32_t count = whole(n, named("planeCount") + "[]", 2, 4096);
            for (const json& target : targets.empty() ? json::array({"float16"}) : targets) {
                const std::string t = target.is_string() ? target.get<std::string>() : echo(target);
                if (t != "float16" && t != "float32" && t != "rgba8" && t != "rgba8-dither")
                    fail(named("planeTargets") + "[] = " + echo(target) +
                         ": must be float16, float32, rgba8 (the seed's rounding) or rgba8-dither");
                emit("planes " + std::to_string(count) + " " + t, [&](BenchRun& r) {
                    r.method = lightscatter::Method::Planes;
                    r.settings.planeCount = count;
                    r.settings.planeTarget = t == "float16" ? lightscatter::PlaneTarget::Float16
                                             : t == "float32"
                                                 ? lightscatter::PlaneTarget::Float32
                                                 : lightscatter::PlaneTarget::Rgba8Channels;
                    r.settings.planeDither = t == "rgba8-dither";
                });
            }
        });
        // Seed 004's simplified light model against the full one, for each method of the
        // configuration that honours it (beam-tree-analytic, analytic); both are measured against
        // the full model's float64 reference.
        sweep("lightModel", "lightModel", false, [&](const json& v, auto emit) {
            const std::string name = v.is_string() ? v.get<std::string>() : echo(v);
            if (name != "full" && name != "simplified")
                fail("sweeps.lightModel[] = " + echo(v) + ": must be full or simplified");
            bool any = false;
            for (const MethodName& m : methods) {
                if (m.method != lightscatter::Method::BeamTreeAnalytic &&
                    m.method != lightscatter::Method::Analytic)
                    continue;
                any = true;
                emit(m.name + " lightModel=" + name, [&](BenchRun& r) {
                    useMethod(r, m);
                    r.settings.lightModel = name == "simplified"
                                                ? lightscatter::LightModel::Simplified
                                                : lightscatter::LightModel::Full;
                });
            }
            if (!any)
                fail("sweeps.lightModel needs method beam-tree-analytic or analytic in methods");
        });
        sweep("size", "size", false, [&](const json& v, auto emit) {
            const VkExtent2D s = size(v, "sweeps.size[]");
            for (const MethodName& m : methods)
                emit(m.name + " size=" + v.get<std::string>(), [&](BenchRun& r) {
                    useMethod(r, m);
                    r.size = s;
                    r.measureError = c.measureError && r.size.width == c.size.width &&
                                     r.size.height == c.size.height;
                });
        });
    }

    std::string path_, root_;
};

}  // namespace

BenchConfig loadBenchConfig(const std::string& path, const std::string& projectRoot) {
    return ConfigReader(path, projectRoot).read();
}

}  // namespace host::bench
