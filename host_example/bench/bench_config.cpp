#include "bench_config.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "cli_args.h"

namespace host::bench {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw std::runtime_error(path + ": " + what);
}

std::string profileLabel(lightscatter::Profile p) { return lightscatter::profileName(p); }

}  // namespace

BenchConfig loadBenchConfig(const std::string& path, const std::string& projectRoot) {
    std::ifstream in(path);
    if (!in) fail(path, "cannot open the benchmark configuration");
    json j;
    try {
        j = json::parse(in);
    } catch (const json::exception& e) {
        fail(path, std::string("malformed JSON: ") + e.what());
    }
    for (const auto& [key, value] : j.items())
        if (key != "name" && key != "frames" && key != "warmup" && key != "size" && key != "scenes" &&
            key != "methods" && key != "profiles" && key != "sweeps")
            fail(path, "unknown key '" + key + "' (known: name, frames, warmup, size, scenes, methods, profiles, sweeps)");
    BenchConfig c;
    try {
        c.name = j.value("name", std::filesystem::path(path).stem().string());
        c.frames = j.value("frames", 10);
        c.warmup = j.value("warmup", 3);
        if (c.frames < 1 || c.frames > 10000) fail(path, "frames must be in [1, 10000]");
        if (c.warmup < 0 || c.warmup > 10000) fail(path, "warmup must be in [0, 10000]");
        c.size = parseSize(j.value("size", std::string("480x270")), "size");
        for (const auto& s : j.at("scenes")) {
            std::filesystem::path p = s.get<std::string>();
            if (p.is_relative()) p = std::filesystem::path(projectRoot) / p;
            c.scenes.push_back(p.string());
        }
        std::vector<lightscatter::Profile> profiles;
        for (const auto& p : j.value("profiles", json::array({"balanced"}))) {
            const auto parsed = lightscatter::parseProfile(p.get<std::string>());
            if (!parsed || *parsed == lightscatter::Profile::Custom)
                fail(path, "profiles: unknown profile '" + p.get<std::string>() + "'");
            profiles.push_back(*parsed);
        }
        std::vector<lightscatter::Method> methods;
        for (const auto& m : j.value("methods", json::array({"epipolar", "brute-force"}))) {
            const auto parsed = lightscatter::parseMethod(m.get<std::string>());
            if (!parsed) fail(path, "methods: unknown method '" + m.get<std::string>() + "'");
            methods.push_back(*parsed);
        }
        const json sweeps = j.value("sweeps", json::object());
        for (const auto& [key, value] : sweeps.items())
            if (key != "slices" && key != "samples" && key != "initialStep" && key != "shadowMapSize" &&
                key != "size" && key != "minMaxTrees")
                fail(path, "sweeps: unknown key '" + key + "'");

        for (const std::string& scene : c.scenes) {
            BenchRun base;
            base.scene = scene;
            base.size = c.size;
            base.measureError = true;
            for (lightscatter::Method m : methods) {
                if (m == lightscatter::Method::BruteForce) {
                    BenchRun r = base;
                    r.method = m;
                    r.family = "profiles";
                    r.label = "brute-force";
                    c.runs.push_back(r);
                    continue;
                }
                for (lightscatter::Profile p : profiles) {
                    BenchRun r = base;
                    r.method = m;
                    r.profile = p;
                    r.family = "profiles";
                    r.label = "epipolar " + profileLabel(p);
                    c.runs.push_back(r);
                }
            }
            // One-parameter sweeps from the balanced profile.
            auto balanced = [&](const std::string& family, const std::string& label) {
                BenchRun r = base;
                r.family = family;
                r.label = label;
                r.custom = true;
                r.settings = lightscatter::profileSettings(lightscatter::Profile::Balanced);
                return r;
            };
            if (sweeps.contains("slices"))
                for (const auto& v : sweeps["slices"]) {
                    BenchRun r = balanced("slices", "slices=" + std::to_string(v.get<int>()));
                    r.settings.slices = v.get<uint32_t>();
                    c.runs.push_back(r);
                }
            if (sweeps.contains("samples"))
                for (const auto& v : sweeps["samples"]) {
                    BenchRun r = balanced("samples", "samples=" + std::to_string(v.get<int>()));
                    r.settings.samplesPerSlice = v.get<uint32_t>();
                    c.runs.push_back(r);
                }
            if (sweeps.contains("initialStep"))
                for (const auto& v : sweeps["initialStep"]) {
                    BenchRun r = balanced("initialStep", "initialStep=" + std::to_string(v.get<int>()));
                    r.settings.initialSampleStep = v.get<uint32_t>();
                    c.runs.push_back(r);
                }
            if (sweeps.contains("minMaxTrees"))
                for (const auto& v : sweeps["minMaxTrees"]) {
                    BenchRun r = balanced("trees", std::string("minMaxTrees=") + (v.get<bool>() ? "on" : "off"));
                    r.settings.minMaxTrees = v.get<bool>();
                    c.runs.push_back(r);
                }
            if (sweeps.contains("shadowMapSize"))
                for (const auto& v : sweeps["shadowMapSize"])
                    for (lightscatter::Method m : methods) {
                        BenchRun r = balanced("shadowMapSize", std::string(lightscatter::methodName(m)) +
                                                                   " shadowMap=" + std::to_string(v.get<int>()));
                        r.method = m;
                        r.shadowMapSize = v.get<uint32_t>();
                        c.runs.push_back(r);
                    }
            if (sweeps.contains("size"))
                for (const auto& v : sweeps["size"])
                    for (lightscatter::Method m : methods) {
                        BenchRun r = balanced("size", std::string(lightscatter::methodName(m)) + " size=" +
                                                          v.get<std::string>());
                        r.method = m;
                        r.size = parseSize(v.get<std::string>(), "sweeps.size");
                        r.measureError = r.size.width == c.size.width && r.size.height == c.size.height;
                        c.runs.push_back(r);
                    }
        }
    } catch (const json::exception& e) {
        fail(path, std::string("a field has the wrong type: ") + e.what());
    }
    if (c.scenes.empty()) fail(path, "scenes is empty");
    return c;
}

}  // namespace host::bench
