// lightscatter bench [--config FILE.json] [--out DIR] [--device NAME] [--validation]
// Runs every configuration of the benchmark file on its scenes: GPU timestamps (warm-up frames,
// then the median and spread of the measured frames, per pass and in total) and the error of Lin
// against the float64 reference with exact visibility. Results go to DIR/bench.csv (a row per run,
// written as each run ends, so an interrupted benchmark keeps what it finished), DIR/bench.json,
// DIR/strips/*.png (reference | method | error heat map) and DIR/references/*.exr (cached).
// With "motion" in the configuration, each run renders the motion's frames instead (the light or
// the camera moving slowly) and its row also carries the flicker against the reference's own
// change from frame to frame (bench/flicker.h), with a heat map of where it is (*_flicker.png).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <utility>

#include "activity.h"
#include "bench/bench_config.h"
#include "bench/csv_file.h"
#include "bench/flicker.h"
#include "bench/image_strip.h"
#include "bench/metrics.h"
#include "bench/profile_order.h"
#include "bench/reference_cache.h"
#include "commands.h"
#include "engine_renderer.h"
#include "image_io.h"
#include "output_set.h"
#include "scene/json_input.h"
#include "scene_inputs.h"
#include "settings_fields.h"
#include "temp_files.h"

namespace host {
namespace {

namespace fs = std::filesystem;

std::string duration(double seconds) {
    char buf[32];
    const int s = static_cast<int>(std::lround(seconds));
    if (s >= 3600)
        std::snprintf(buf, sizeof buf, "%dh%02dm", s / 3600, (s / 60) % 60);
    else
        std::snprintf(buf, sizeof buf, "%dm%02ds", s / 60, s % 60);
    return buf;
}

// A progress line redrawn in place on stderr. It is ended with a newline when the benchmark ends
// or fails, so that an error is printed on a line of its own, not after the bar.
class Progress {
  public:
    explicit Progress(size_t total) : total_(total), start_(std::chrono::steady_clock::now()) {}
    ~Progress() { finish(); }
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    void finish() {
        if (open_) std::fputc('\n', stderr);
        open_ = false;
    }
    void show(size_t done, const std::string& what) {
        open_ = true;
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const double left =
            done ? elapsed / static_cast<double>(done) * static_cast<double>(total_ - done) : 0.0;
        const int width = 30;
        const int filled = static_cast<int>(width * done / std::max<size_t>(total_, 1));
        std::fprintf(stderr, "\r[%s%s] %zu/%zu, %s elapsed, %s left  %-60.60s",
                     std::string(filled, '#').c_str(), std::string(width - filled, ' ').c_str(),
                     done, total_, duration(elapsed).c_str(),
                     done ? ("~" + duration(left)).c_str() : "?", what.c_str());
        std::fflush(stderr);
    }

  private:
    size_t total_;
    std::chrono::steady_clock::time_point start_;
    bool open_ = false;
};

const char* kCsvHeader =
    "scene,label,family,method,profile,width,height,slices,samples,initialStep,minMaxTrees,"
    "shadowMap,frames,medianMs,p10Ms,p90Ms,minMs,maxMs,meanRelativeError,rmse,p99Error,maxError,"
    "fractionOver5pct,psnrDb,nonFinite,device,cpuDevice,cpuWorkMs,occluders,lights,motion,"
    "framePairs,"
    "meanExcessFlicker,p99ExcessFlicker,meanErrorChange,referenceChange,motionMeanRelativeError";

nlohmann::json spreadJson(const bench::Spread& s) {
    return {{"median", s.median}, {"p10", s.p10},   {"p90", s.p90}, {"min", s.min},
            {"max", s.max},       {"mean", s.mean}, {"sd", s.sd}};
}

// Each named entry of the last frame (a pass, a piece of CPU work) with its spread over the frames.
nlohmann::json namedSpreads(const std::vector<lightscatter::PassTime>& entries,
                            std::map<std::string, std::vector<double>>& perName) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& e : entries) {
        const bench::Spread s = bench::spreadOf(perName[e.name]);
        list.push_back({{"name", e.name}, {"median", s.median}, {"p10", s.p10}, {"p90", s.p90}});
    }
    return list;
}

// Where a run's image strip goes: scene, label and motion ("" for a still frame) made file-safe.
fs::path stripPath(const fs::path& out, const bench::BenchRun& run, const std::string& motion,
                   const std::string& suffix) {
    const std::string strip = fs::path(run.scene).stem().string() + "_" + run.label +
                              (motion.empty() ? "" : "_motion-" + motion);
    return out / "strips" / (bench::fileSafe(strip) + suffix);
}

// Runs the benchmark passes over without a word: a light or scene its method has nothing to
// measure on.
bool skipped(const bench::BenchRun& run, const SceneDesc& scene) {
    // A method that does not take the scene's light (its type, its shadow map: methodInfo()).
    for (const lightscatter::MethodInfo& m : lightscatter::methodInfo()) {
        if (m.method != run.method) continue;
        const lightscatter::LightType type = scene.light.type;
        if (!(type == lightscatter::LightType::Directional ? m.directional
              : type == lightscatter::LightType::Spot      ? m.spot
                                                           : m.point))
            return true;
        if (scene.light.shadowMapSize > 0 &&
            !(type == lightscatter::LightType::Point ? m.cubeShadow : m.shadowMap))
            return true;
    }
    // A shadow-map sweep resizes the light's map; a light without one (point_fog's) keeps none:
    // a point light given a size would get a cube map, which is another scene, not a size.
    return run.shadowMapSize && scene.light.shadowMapSize == 0;
}

RenderOptions runOptions(const bench::BenchRun& run) {
    RenderOptions options;
    options.method = run.method;
    options.profile = run.custom ? lightscatter::Profile::Custom : run.profile;
    // With a profile, it decides its fields over these (a preset's settings, or the defaults).
    options.custom = run.settings;
    return options;
}

// Every run's frame against the plugin's rules, before the first is timed: a method that cannot
// honour a scene's lights used to end the benchmark when its run came up, hours in, naming no
// scene. One small renderer per scene asks the plugin (Plugin::check), rendering nothing.
void checkEveryRun(const rg::Device& device, const bench::BenchConfig& config,
                   const std::string& configPath,
                   const std::map<std::string, std::pair<SceneDesc, MeshData>>& scenes) {
    std::map<std::string, std::unique_ptr<EngineRenderer>> probes;
    for (const bench::BenchRun& run : config.runs) {
        const auto& [scene, mesh] = scenes.at(run.scene);
        if (skipped(run, scene)) continue;
        std::unique_ptr<EngineRenderer>& probe = probes[run.scene];
        if (!probe)
            probe = std::make_unique<EngineRenderer>(device, scene, mesh, VkExtent2D{16, 16});
        try {
            probe->check(runOptions(run));
        } catch (const SceneError& e) {
            throw std::runtime_error(configPath + ": run '" + echoText(run.label) +
                                     "' cannot run on " + e.what());
        }
    }
}

}  // namespace

int runBench(Args& args) {
    const std::string root = LS_PROJECT_ROOT;
    const std::string configPath = args.take("--config", root + "/bench/small.json");
    const fs::path out = args.take("--out", "bench-results");
    rg::DeviceOptions deviceOptions;
    deviceOptions.deviceName = args.take("--device", "");
    deviceOptions.validation = args.flag("--validation");
    args.finish();
    // Everything that can be checked is checked before the first run: every run's values (in
    // loadBenchConfig), every scene and its models, the output folder.
    const bench::BenchConfig config = bench::loadBenchConfig(configPath, root);
    std::map<std::string, std::pair<SceneDesc, MeshData>> scenes;
    for (const std::string& path : config.scenes) {
        if (scenes.count(path)) continue;
        SceneDesc s = loadSceneFile(path);
        MeshData m = loadSceneMeshes(s);
        for (const auto& w : m.warnings) std::cerr << "lightscatter: warning: " << w << "\n";
        scenes.emplace(path, std::make_pair(std::move(s), std::move(m)));
    }
    // The benchmark writes as it goes, so every file it will write is checked against what it
    // reads (and what the scenes beside it read) before the first run: `--config D/bench.json
    // --out D` used to replace the configuration with its results.
    OutputSet guard;
    guard.addInput("the benchmark configuration", configPath);
    for (const auto& [path, scene] : scenes)
        addSceneInputs(guard, path, scene.first, scene.second, "a scene of the benchmark");
    guard.check("--out", (out / "bench.csv").string());
    guard.check("--out", (out / "bench.json").string());
    // Labels that differ only where a file name cannot (a/b and a_b) would share a strip, and the
    // later run's would replace the earlier's.
    std::map<std::string, const bench::BenchRun*> strips;
    for (const bench::BenchRun& run : config.runs) {
        if (!run.measureError) continue;  // no strip without a reference
        std::vector<std::string> motions{""};
        if (config.motion) {
            motions.clear();
            for (const bench::MotionKind m : config.motion->what)
                motions.push_back(bench::motionName(m));
        }
        for (const std::string& m : motions)
            for (const char* suffix : {".png", "_flicker.png"}) {
                if (m.empty() && std::string(suffix) != ".png") continue;
                const fs::path strip = stripPath(out, run, m, suffix);
                guard.check("--out", strip.string());
                const auto [it, fresh] = strips.emplace(strip.string(), &run);
                if (!fresh)
                    throw std::runtime_error(
                        configPath + ": runs '" + echoText(it->second->label) + "' on " +
                        echoText(fs::path(it->second->scene).stem().string()) + " and '" +
                        echoText(run.label) + "' on " +
                        echoText(fs::path(run.scene).stem().string()) +
                        " would write the same strip " + echoText(strip.filename().string()) +
                        ": give them labels that differ in letters or digits");
            }
    }
    Activity benchmarking("benchmarking " + configPath);
    rg::Device device(deviceOptions);
    checkEveryRun(device, config, configPath, scenes);
    for (const fs::path& dir : {out / "strips", out / "references"}) {
        std::error_code ec;
        fs::create_directories(dir, ec);
        if (ec)
            throw std::runtime_error("--out " + out.string() + ": cannot create " + dir.string() +
                                     ": " + ec.message());
    }
    { TempFile probe((out / "bench.json").string(), "--out"); }  // the folder is writable

    bench::CsvFile csv((out / "bench.csv").string(), kCsvHeader);
    nlohmann::json all = nlohmann::json::array();
    Progress progress(config.runs.size());

    std::map<std::string, std::vector<double>> references;
    std::string referencesScene;
    std::unique_ptr<EngineRenderer> renderer;
    std::string rendererKey;
    size_t done = 0;
    for (const bench::BenchRun& run : config.runs) {
        const std::string what = fs::path(run.scene).stem().string() + ": " + run.label;
        progress.show(done, what);
        // The runs come scene by scene: a motion's references (one per frame) are kept in memory
        // for the runs of their scene only.
        if (run.scene != referencesScene) references.clear();
        referencesScene = run.scene;
        auto& [scene, mesh] = scenes.at(run.scene);
        if (skipped(run, scene)) {
            ++done;
            continue;
        }
        SceneDesc sceneForRun = scene;
        if (run.shadowMapSize) sceneForRun.light.shadowMapSize = run.shadowMapSize;
        // A profile's map for a shadowed light; a light without a map keeps none.
        const bool profileMap = run.profileShadowMap && scene.light.shadowMapSize != 0;
        if (profileMap) sceneForRun.light.shadowMapSize = run.profileShadowMap;
        const std::string key = run.scene + "/" + std::to_string(run.size.width) + "x" +
                                std::to_string(run.size.height) + "/" +
                                std::to_string(sceneForRun.light.shadowMapSize);
        if (key != rendererKey) {
            renderer.reset();
            renderer =
                std::make_unique<EngineRenderer>(device, sceneForRun, mesh, run.size,
                                                 configPath + ": run '" + run.label + "' at size");
            rendererKey = key;
        }
        const RenderOptions options = runOptions(run);
        const lightscatter::Settings used = lightscatter::profileSettings(
            run.custom ? lightscatter::Profile::Custom : run.profile, run.settings);

        // The reference for the renderer's scene as it stands, once per pose in memory, and on
        // disk across runs of the benchmark.
        auto reference = [&](const std::string& memo,
                             const std::string& doing) -> const std::vector<double>& {
            if (!references.count(memo)) {
                int shown = -1;
                references[memo] = bench::loadOrRenderReference(
                    renderer->scene(), mesh, run.size, out / "references", [&](double f) {
                        const int percent = static_cast<int>(f * 100);
                        if (percent / 10 == shown / 10) return;  // a line every 10%, not every row
                        shown = percent;
                        progress.show(done, what + " (reference" + doing + " " +
                                                std::to_string(percent) + "%)");
                    });
            }
            return references[memo];
        };
        // Still frames, or (with a motion) each motion in turn from the scene's own pose.
        std::vector<std::optional<bench::MotionKind>> passes{std::nullopt};
        if (config.motion && run.measureError)
            passes.assign(config.motion->what.begin(), config.motion->what.end());
        for (const std::optional<bench::MotionKind>& motion : passes) {
            renderer->scene().camera = sceneForRun.camera;
            renderer->scene().light = sceneForRun.light;
            // Each pass starts again from the scene's own pose: a camera cut, so a method that
            // keeps history (froxels' temporal mode) forgets the pass before's last pose.
            bool cut = true;
            auto renderFrame = [&] {
                RenderOptions o = options;
                o.resetHistory = std::exchange(cut, false);
                return renderer->render(o);
            };
            for (int i = 0; i < config.warmup; ++i) renderFrame();
            // The plugin's passes, the host's own (shadow map and shading) and the two together:
            // seed 003 times whole frames against a baseline without the effect.
            std::vector<double> totals, cpuTotals, engineTotals, frameTotals;
            std::map<std::string, std::vector<double>> perPass, perCpuWork;
            FrameOutput last;
            bench::FlickerMeter flicker;
            const std::vector<double>* lastReference = nullptr;
            const int frames = motion ? config.motion->frames : config.frames;
            const std::string motionName = motion ? bench::motionName(*motion) : "";
            for (int i = 0; i < frames; ++i) {
                if (motion) {
                    const SceneDesc pose = bench::poseAt(sceneForRun, *motion, *config.motion, i);
                    renderer->scene().camera = pose.camera;
                    renderer->scene().light = pose.light;
                }
                last = renderFrame();
                totals.push_back(last.plugin.totalMilliseconds);
                engineTotals.push_back(last.engine.totalMilliseconds);
                frameTotals.push_back(last.engine.totalMilliseconds +
                                      last.plugin.totalMilliseconds);
                for (const auto& p : last.plugin.passes) perPass[p.name].push_back(p.milliseconds);
                double cpu = 0.0;
                for (const auto& w : last.plugin.cpuWork) {
                    perCpuWork[w.name].push_back(w.milliseconds);
                    cpu += w.milliseconds;
                }
                cpuTotals.push_back(cpu);
                if (motion) {
                    // A still pass's frames share one pose, so one reference.
                    const int pose = *motion == bench::MotionKind::Still ? 0 : i;
                    lastReference =
                        &reference(run.scene + "|" + motionName + "|" + std::to_string(pose),
                                   " " + motionName + " " + std::to_string(i + 1) + "/" +
                                       std::to_string(frames));
                    flicker.add(last.inscatter, *lastReference);
                }
            }
            renderer->scene().camera = sceneForRun.camera;
            renderer->scene().light = sceneForRun.light;
            const bench::Spread t = bench::spreadOf(totals);
            const bench::Spread cpu = bench::spreadOf(cpuTotals);

            nlohmann::json row;
            row["scene"] = fs::path(run.scene).stem().string();
            row["label"] = run.label;
            row["family"] = run.family;
            row["method"] = lightscatter::methodName(run.method);
            row["methodRan"] = last.plugin.method;  // with auto, the method it picked
            // Which nodes ran and why, and what the last frame placed (its sampling planes).
            row["reason"] = last.plugin.reason;
            // Every setting the run used, as a settings file gives them; and, under the names
            // the report's scripts read, the ones they tabulate.
            row["settings"] = nlohmann::json::parse(settingsFileText(used));
            row["coneSamples"] = used.coneMarch.samples;
            row["coneLimited"] = used.coneMarch.limited;
            row["shadowSampling"] = used.shadowSampling;
            row["lightModel"] =
                used.lightModel == lightscatter::LightModel::Simplified ? "simplified" : "full";
            row["profile"] = run.custom ? "custom" : lightscatter::profileName(run.profile);
            row["size"] = {run.size.width, run.size.height};
            row["round"] = run.round + 1;
            row["slices"] = used.epipolar.slices;
            row["samples"] = used.epipolar.samplesPerSlice;
            row["initialStep"] = used.epipolar.initialSampleStep;
            row["minMaxTrees"] = used.epipolar.minMaxTrees;
            row["shadowMapSize"] = sceneForRun.light.shadowMapSize;
            row["shadowMapFrom"] = profileMap          ? run.shadowMapFrom
                                   : run.shadowMapSize ? std::string("sweep")
                                                       : std::string("scene");
            row["frames"] = frames;
            row["warmup"] = config.warmup;
            row["time"] = spreadJson(t);
            row["engineTime"] = spreadJson(bench::spreadOf(engineTotals));
            row["frameTime"] = spreadJson(bench::spreadOf(frameTotals));
            row["passes"] = namedSpreads(last.plugin.passes, perPass);
            // Epipolar's ray-marched samples, counted by its marches: the first march, and the
            // samples the refinement on in-scattering differences added.
            uint64_t marched = 0, refined = 0;
            for (const auto& p : last.plugin.passes) {
                if (p.samples < 0) continue;
                (p.name.find("(refinement") != std::string::npos ? refined : marched) +=
                    static_cast<uint64_t>(p.samples);
            }
            if (run.method == lightscatter::Method::Epipolar || last.plugin.method == "epipolar") {
                row["marchedSamples"] = marched;
                row["refinedSamples"] = refined;
                row["inscatterRefinementThreshold"] = used.epipolar.inscatterRefinementThreshold;
            }
            // The plugin's CPU work per frame (the beam tree), outside the GPU time above.
            row["cpuTime"] = spreadJson(cpu);
            row["cpuWork"] = namedSpreads(last.plugin.cpuWork, perCpuWork);
            row["occluders"] = renderer->occluderCount();
            row["lights"] = scene.lightCount();
            row["device"] = device.name();
            row["driver"] = device.driverName();
            row["cpuDevice"] = device.isCpu();

            using bench::csvNumber;
            std::vector<std::string> errorColumns(6), motionColumns(7);
            size_t nonFinite = 0;
            for (float v : last.inscatter) nonFinite += std::isfinite(v) ? 0 : 1;
            if (run.measureError) {
                // A motion's row is judged on its last frame here, and on every frame below.
                const std::vector<double>& ref = motion ? *lastReference : reference(run.scene, "");
                const bench::ErrorMetrics e =
                    bench::compareToReference(last.inscatter, ref, scene.exposure);
                nonFinite = e.nonFinite;
                row["error"] = {{"meanRelative", e.meanRelative},
                                {"rmse", e.rmse},
                                {"p99", e.p99},
                                {"max", e.max},
                                {"fractionOver5pct", e.fractionOver},
                                {"psnrDb", e.psnr}};
                errorColumns = {csvNumber("%.6g", e.meanRelative), csvNumber("%.6g", e.rmse),
                                csvNumber("%.6g", e.p99),          csvNumber("%.6g", e.max),
                                csvNumber("%.6g", e.fractionOver), csvNumber("%.3f", e.psnr)};
                bench::writeStrip(stripPath(out, run, motionName, ".png").string(), run.size.width,
                                  run.size.height, ref, last.inscatter, scene.exposure);
                if (motion) {
                    const bench::FlickerMetrics f = flicker.result();
                    const bench::Motion& m = *config.motion;
                    row["motion"] = {{"what", motionName},
                                     {"frames", m.frames},
                                     {"lightDegreesPerFrame", m.lightDegreesPerFrame},
                                     {"lightMetresPerFrame", m.lightMetresPerFrame},
                                     {"cameraMetresPerFrame", m.cameraMetresPerFrame},
                                     {"cameraDegreesPerFrame", m.cameraDegreesPerFrame}};
                    row["flicker"] = {{"framePairs", f.framePairs},
                                      {"meanExcess", f.meanExcess},
                                      {"p99Excess", f.p99Excess},
                                      {"maxExcess", f.maxExcess},
                                      {"meanErrorChange", f.meanErrorChange},
                                      {"p99ErrorChange", f.p99ErrorChange},
                                      {"methodChange", f.methodChange},
                                      {"referenceChange", f.referenceChange},
                                      {"meanRelativeError", f.meanRelativeError},
                                      {"nonFinite", f.nonFinite}};
                    motionColumns = {motionName,
                                     std::to_string(f.framePairs),
                                     csvNumber("%.6g", f.meanExcess),
                                     csvNumber("%.6g", f.p99Excess),
                                     csvNumber("%.6g", f.meanErrorChange),
                                     csvNumber("%.6g", f.referenceChange),
                                     csvNumber("%.6g", f.meanRelativeError)};
                    bench::writeFlickerStrip(
                        stripPath(out, run, motionName, "_flicker.png").string(), run.size.width,
                        run.size.height, flicker.referenceChangeMap(), flicker.excessMap());
                }
            }
            row["nonFinite"] = nonFinite;
            std::vector<std::string> fields = {row["scene"].get<std::string>(),
                                               run.label,
                                               run.family,
                                               lightscatter::methodName(run.method),
                                               row["profile"].get<std::string>(),
                                               std::to_string(run.size.width),
                                               std::to_string(run.size.height),
                                               std::to_string(used.epipolar.slices),
                                               std::to_string(used.epipolar.samplesPerSlice),
                                               std::to_string(used.epipolar.initialSampleStep),
                                               used.epipolar.minMaxTrees ? "1" : "0",
                                               std::to_string(sceneForRun.light.shadowMapSize),
                                               std::to_string(frames),
                                               csvNumber("%.6f", t.median),
                                               csvNumber("%.6f", t.p10),
                                               csvNumber("%.6f", t.p90),
                                               csvNumber("%.6f", t.min),
                                               csvNumber("%.6f", t.max)};
            fields.insert(fields.end(), errorColumns.begin(), errorColumns.end());
            for (const std::string& f :
                 {std::to_string(nonFinite), device.name(), std::string(device.isCpu() ? "1" : "0"),
                  csvNumber("%.6f", cpu.median), std::to_string(renderer->occluderCount()),
                  std::to_string(scene.lightCount())})
                fields.push_back(f);
            fields.insert(fields.end(), motionColumns.begin(), motionColumns.end());
            csv.append(bench::csvRow(fields));
            all.push_back(row);
            writeTextFile((out / "bench.json").string(),
                          nlohmann::json{{"config", config.name}, {"runs", all}}.dump(2) + "\n");
        }
        ++done;
    }
    progress.show(done, "done");
    progress.finish();
    bool outOfOrder = false;
    if (config.profileOrder) {
        const bench::ProfileOrderCheck check =
            bench::checkProfileOrder(all, config.profileOrder->tolerance);
        nlohmann::json broken = nlohmann::json::array();
        for (const std::string& line : check.broken) {
            std::cout << "profile order: " << line << "\n";
            broken.push_back(line);
        }
        std::cout << "profile order: " << check.pairs - check.broken.size() << " of " << check.pairs
                  << " neighbouring profiles in order (tolerance "
                  << config.profileOrder->tolerance * 100.0 << "%)\n";
        writeTextFile((out / "bench.json").string(),
                      nlohmann::json{{"config", config.name},
                                     {"runs", all},
                                     {"profileOrder",
                                      {{"tolerance", config.profileOrder->tolerance},
                                       {"pairs", check.pairs},
                                       {"outOfOrder", broken}}}}
                              .dump(2) +
                          "\n");
        outOfOrder = !check.broken.empty();
    }
    std::cout << "wrote " << (out / "bench.csv").string() << ", bench.json and " << done
              << " runs' strips (" << device.name() << (device.isCpu() ? ", CPU timings" : "")
              << ")\n";
    if (device.messageCount() > 0) return 3;
    return outOfOrder ? 4 : 0;
}

}  // namespace host
