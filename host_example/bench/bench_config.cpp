#include "bench_config.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

#include "cli_args.h"
#include "scene/input_file.h"
#include "scene/json_input.h"
#include "settings_fields.h"

namespace host::bench {
namespace {

// A method as a configuration names it: its own name, or a preset's (MethodInfo::presets), which
// is the method with the preset's settings.
struct MethodName {
    lightscatter::Method method;
    std::string name;
    bool preset = false;
};

using nlohmann::json;

// A run of a method: its enum value, and a preset's settings over the run's.
void useMethod(BenchRun& r, const MethodName& m) {
    r.method = m.method;
    if (m.preset) (void)lightscatter::applyMethodPreset(m.name, r.settings);
}

// The method whose own field this is (its group is the method's settings member); none for
// Settings' shared fields.
std::optional<lightscatter::Method> owner(const SettingField& f) {
    for (const lightscatter::MethodInfo& m : lightscatter::methodInfo())
        for (const SettingField& own : m.settings)
            if (own.name == f.name) return m.method;
    return std::nullopt;
}

// A value as a run's label gives it: a number (the shortest text that reads back as it, so that
// 0.9900001 is not labelled 0.99 beside a message that quotes 0.9900001), on or off, a choice's
// name.
std::string valueText(const json& v) {
    if (v.is_boolean()) return v.get<bool>() ? "on" : "off";
    if (v.is_string()) return v.get<std::string>();
    if (v.is_number_float()) return shortestText(v.get<double>());
    return v.dump();
}

constexpr uint64_t kConfigFileCap = 1 * kMiB;
// A configuration's runs are its scenes times its methods, profiles and sweep values: they grow as
// the square of the file (1000 scenes and 1000 sweep values are 30 KB and a million runs, each
// checked with the plugin's budget). The largest shipped one, bench/full.json, has 420.
constexpr size_t kMaxRuns = 10000;

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
                key != "profileShadowMap" && key != "configurations" && key != "profileOrder")
                fail("unknown key '" + echoText(key) +
                     "' (known: name, frames, warmup, size, scenes, methods, profiles, sweeps, "
                     "sweepProfile, measureError, motion, profileShadowMap, configurations, "
                     "profileOrder)");
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
        // A sweep's key is a settings field (its name, or a former one) or the benchmark's
        // own shadowMapSize (the scenes' maps) and size.
        std::vector<const SettingField*> swept;
        for (const auto& [key, value] : sweeps.items()) {
            if (key == "shadowMapSize" || key == "size") continue;
            const SettingField* f = findSettingField(key);
            if (!f)
                fail("sweeps: unknown key '" + echoText(key) +
                     "' (known: shadowMapSize, size, and every settings field: " +
                     knownFieldNames() + ")");
            if (std::find(swept.begin(), swept.end(), f) != swept.end())
                fail("sweeps." + key + " sweeps " + f->name +
                     " a second time (under another of its names): give it once");
            swept.push_back(f);
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
        if (j.contains("profileOrder")) c.profileOrder = profileOrder(j["profileOrder"], c);
        if (profileShadowMap) applyProfileShadowMaps(c, profiles);
        distinct(c);
        return c;
    }

  private:
    // A run is known in bench.csv and bench.json by its scene's name and its label: two runs alike
    // there were two measurements of which one row could not be told from the other.
    void distinct(const BenchConfig& c) const {
        std::map<std::string, std::string> sceneByName;
        for (const std::string& s : c.scenes) {
            const std::string name = std::filesystem::path(s).stem().string();
            const auto [it, fresh] = sceneByName.emplace(name, s);
            if (!fresh && it->second != s)
                fail("scenes '" + echoText(it->second) + "' and '" + echoText(s) +
                     "' are both named '" + echoText(name) +
                     "': their rows and strips would not be told apart; rename one");
        }
        std::set<std::pair<std::string, std::string>> seen;
        for (const BenchRun& r : c.runs) {
            const std::string name = std::filesystem::path(r.scene).stem().string();
            if (!seen.emplace(name, r.label).second)
                fail("the run labelled '" + echoText(r.label) + "' comes twice on " +
                     echoText(name) +
                     " (a scene or a size given twice, or a configuration labelled as another "
                     "run is): one row would not be told from the other");
        }
    }

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
            lightscatter::Settings unused;
            if (const auto preset = lightscatter::applyMethodPreset(method, unused)) {
                methods.push_back({*preset, method, true});
                continue;
            }
            const auto parsed = lightscatter::parseMethod(method);
            if (!parsed) {
                std::string known;
                for (const auto& k : lightscatter::methodNames())
                    known += (known.empty() ? "" : ", ") + k;
                for (const lightscatter::MethodInfo& info : lightscatter::methodInfo())
                    for (const lightscatter::MethodPreset& p : info.presets) known += ", " + p.name;
                fail(name + ": unknown method '" + echoText(method) + "' (known: " + known + ")");
            }
            methods.push_back({*parsed, lightscatter::methodName(*parsed), false});
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
    // object[key] (named `at`.key), fallback where it is not given.
    double number(const json& object, const std::string& at, const char* key, double fallback,
                  double lo, double hi) const {
        if (!object.contains(key)) return fallback;
        const json& v = object[key];
        const std::string name = at + "." + key;
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
            fail("motion.what is required: \"light\", \"camera\", \"still\" or an array of them");
        Motion m;
        const json what = v["what"].is_string() ? json::array({v["what"]}) : v["what"];
        if (!what.is_array() || what.empty())
            fail("motion.what = " + echo(v["what"]) +
                 ": must be \"light\", \"camera\", \"still\" or a non-empty array of them");
        for (const json& w : what) {
            if (w != "light" && w != "camera" && w != "still")
                fail("motion.what[] = " + echo(w) + ": must be \"light\", \"camera\" or \"still\"");
            const MotionKind kind = w == "light"    ? MotionKind::Light
                                    : w == "camera" ? MotionKind::Camera
                                                    : MotionKind::Still;
            if (std::find(m.what.begin(), m.what.end(), kind) != m.what.end())
                fail("motion.what lists " + echo(w) + " twice");
            m.what.push_back(kind);
        }
        // Two frames make the first pair; the flicker is a change from one frame to the next.
        if (v.contains("frames")) m.frames = int(whole(v["frames"], "motion.frames", 2, 10000));
        m.lightDegreesPerFrame =
            number(v, "motion", "lightDegreesPerFrame", m.lightDegreesPerFrame, 0, 10);
        m.lightMetresPerFrame =
            number(v, "motion", "lightMetresPerFrame", m.lightMetresPerFrame, 0, 10);
        m.cameraMetresPerFrame =
            number(v, "motion", "cameraMetresPerFrame", m.cameraMetresPerFrame, 0, 10);
        m.cameraDegreesPerFrame =
            number(v, "motion", "cameraDegreesPerFrame", m.cameraDegreesPerFrame, 0, 10);
        return m;
    }

    // {"sizes": [...], "tolerance": 0.05, "rounds": 1}: each epipolar profile run once per size
    // (labelled with it; errors only at the configuration's size) and per round, its order
    // checked after the benchmark. A scene's rounds each run all its profiles and sizes in turn:
    // the device's drift over a round then falls on every profile alike.
    ProfileOrder profileOrder(const json& v, BenchConfig& c) const {
        if (!v.is_object()) fail("profileOrder must be an object {\"sizes\": [...]}");
        for (const auto& [key, value] : v.items())
            if (key != "sizes" && key != "tolerance" && key != "rounds")
                fail("profileOrder: unknown key '" + echoText(key) +
                     "' (known: sizes, tolerance, rounds)");
        if (!v.contains("sizes")) fail("profileOrder.sizes is required");
        ProfileOrder o;
        for (const json& s : list(v["sizes"], "profileOrder.sizes")) {
            const VkExtent2D e = size(s, "profileOrder.sizes[]");
            for (const VkExtent2D& earlier : o.sizes)
                if (earlier.width == e.width && earlier.height == e.height)
                    fail("profileOrder.sizes lists " + echo(s) + " twice");
            o.sizes.push_back(e);
        }
        if (o.sizes.empty()) fail("profileOrder.sizes is empty");
        o.tolerance = number(v, "profileOrder", "tolerance", o.tolerance, 0, 10);
        if (v.contains("rounds")) o.rounds = int(whole(v["rounds"], "profileOrder.rounds", 1, 100));
        std::vector<BenchRun> runs;
        // The runs come scene by scene (the references are kept per scene): rounds within each.
        for (size_t at = 0, end = 0; at < c.runs.size(); at = end) {
            while (end < c.runs.size() && c.runs[end].scene == c.runs[at].scene) ++end;
            for (int round = 0; round < o.rounds; ++round)
                for (size_t i = at; i < end; ++i) {
                    const BenchRun& r = c.runs[i];
                    if (r.family != "profiles" || r.method != lightscatter::Method::Epipolar) {
                        if (round == 0) runs.push_back(r);
                        continue;
                    }
                    for (const VkExtent2D& e : o.sizes) {
                        BenchRun sized = r;
                        sized.size = e;
                        sized.round = round;
                        sized.label = r.label + " " + std::to_string(e.width) + "x" +
                                      std::to_string(e.height) +
                                      (round > 0 ? " round " + std::to_string(round + 1) : "");
                        sized.measureError = round == 0 && r.measureError &&
                                             e.width == c.size.width && e.height == c.size.height;
                        runs.push_back(sized);
                    }
                }
        }
        c.runs.clear();
        for (const BenchRun& r : runs) add(c, r);
        return o;
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

    // The plugin's rules for settings.
    void checkSettings(const BenchRun& r, const std::string& where) const {
        try {
            lightscatter::checkSettings(r.settings, "");
        } catch (const lightscatter::InvalidInput& e) {
            std::string why = e.what();
            const std::string lead = "lightscatter: ";
            if (why.rfind(lead, 0) == 0) why.erase(0, lead.size());
            fail(where + " (run '" + echoText(r.label) + "'): " + why);
        }
    }

    // Sets a settings field a configuration or sweep names, its value as a settings file gives it.
    void setField(BenchRun& r, const SettingField& f, const json& v, const std::string& key) const {
        try {
            setFieldFromJson(r.settings, f, v, key);
        } catch (const std::runtime_error& e) {
            fail(e.what());
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
            // The run's own keys, then settings fields (a method's nested under its member, or
            // named in full, or by a former name).
            static const char* const kKeys[] = {"label", "method",        "from",
                                                "sizes", "shadowMapSize", "family"};
            struct Given {
                const SettingField* field;
                std::string key;
                json value;
            };
            std::vector<Given> fields;
            auto field = [&](const std::string& key, const json& value) {
                const SettingField* f = findSettingField(key);
                if (!f)
                    fail(at + ": unknown key '" + echoText(key) +
                         "' (known: label, method, from, sizes, shadowMapSize, family, and every "
                         "settings field: " +
                         knownFieldNames() + ")");
                for (const Given& other : fields)
                    if (other.field == f)
                        fail(at + "." + key + " sets " + f->name + " a second time (as " +
                             other.key + "): give it once");
                fields.push_back({f, key, value});
            };
            for (const auto& item : o.items()) {
                const std::string& key = item.key();
                if (std::find_if(std::begin(kKeys), std::end(kKeys),
                                 [&key](const char* k) { return key == k; }) != std::end(kKeys))
                    continue;
                if (item.value().is_object())
                    for (const auto& inner : item.value().items())
                        field(key + "." + inner.key(), inner.value());
                else
                    field(key, item.value());
            }
            if (!o.contains("label")) fail(at + ".label is required");
            BenchRun r;
            r.family = o.contains("family") ? text(o["family"], at + ".family") : "configurations";
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
            for (const Given& g : fields) setField(r, *g.field, g.value, at + "." + g.key);
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
            // preset with its settings).
            if (m != lightscatter::Method::Epipolar) {
                BenchRun r = base;
                useMethod(r, named);
                r.family = "profiles";
                r.label = named.name;
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
        auto values = [&](const std::string& key) { return list(sweeps[key], "sweeps." + key); };
        // One-parameter sweeps of a settings field from one profile (balanced unless
        // sweepProfile says otherwise): a run per value, of the method whose field it is (the
        // configuration's first method for Settings' shared fields), labelled KEY=VALUE under
        // the key as the file wrote it, and checked by the plugin's rules.
        for (const auto& [key, given] : sweeps.items()) {
            if (key == "shadowMapSize" || key == "size") continue;
            const SettingField& f = *findSettingField(key);
            const std::string where = "sweeps." + key;
            for (const json& v : values(key)) {
                BenchRun r = base;
                r.family = key;
                r.label = key + "=" + valueText(v);
                r.custom = true;
                r.settings = lightscatter::profileSettings(sweepProfile);
                if (const auto m = owner(f))
                    r.method = *m;
                else if (!methods.empty())
                    useMethod(r, methods.front());
                setField(r, f, v, where + "[]");
                checkSettings(r, where);
                add(c, r);
            }
        }
        auto sweep = [&](const char* key, auto emit) {
            if (!sweeps.contains(key)) return;
            for (const json& v : values(key))
                for (const MethodName& m : methods) {
                    BenchRun r = base;
                    r.family = key;
                    r.custom = true;
                    r.settings = lightscatter::profileSettings(sweepProfile);
                    useMethod(r, m);
                    emit(r, v, m);
                    add(c, r);
                }
        };
        sweep("shadowMapSize", [&](BenchRun& r, const json& v, const MethodName& m) {
            r.shadowMapSize = whole(v, "sweeps.shadowMapSize[]", 1, 16384);
            r.label = m.name + " shadowMap=" + std::to_string(r.shadowMapSize);
        });
        sweep("size", [&](BenchRun& r, const json& v, const MethodName& m) {
            r.size = size(v, "sweeps.size[]");
            r.label = m.name + " size=" + v.get<std::string>();
            r.measureError =
                c.measureError && r.size.width == c.size.width && r.size.height == c.size.height;
        });
    }

    std::string path_, root_;
};

}  // namespace

BenchConfig loadBenchConfig(const std::string& path, const std::string& projectRoot) {
    return ConfigReader(path, projectRoot).read();
}

}  // namespace host::bench
