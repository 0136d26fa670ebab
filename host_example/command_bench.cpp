// lightscatter bench [--config FILE.json] [--out DIR] [--device NAME] [--validation]
// Runs every configuration of the benchmark file on its scenes: GPU timestamps (warm-up frames,
// then the median and spread of the measured frames, per pass and in total) and the error of Lin
// against the float64 reference with exact visibility. Results go to DIR/bench.csv (a row per run,
// written as each run ends, so an interrupted benchmark keeps what it finished), DIR/bench.json,
// DIR/strips/*.png (reference | method | error heat map) and DIR/references/*.exr (cached).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

#include "activity.h"
#include "bench/bench_config.h"
#include "bench/image_strip.h"
#include "bench/metrics.h"
#include "commands.h"
#include "engine_renderer.h"
#include "image_io.h"
#include "exact_renderer/reference_renderer.h"
#include "scene/input_file.h"
#include "temp_files.h"

namespace host {
namespace {

namespace fs = std::filesystem;

std::string fileSafe(std::string s) {
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.') c = '_';
    return s;
}

std::string duration(double seconds) {
    char buf[32];
    const int s = static_cast<int>(std::lround(seconds));
    if (s >= 3600) std::snprintf(buf, sizeof buf, "%dh%02dm", s / 3600, (s / 60) % 60);
    else std::snprintf(buf, sizeof buf, "%dm%02ds", s / 60, s % 60);
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
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const double left = done ? elapsed / static_cast<double>(done) * static_cast<double>(total_ - done) : 0.0;
        const int width = 30;
        const int filled = static_cast<int>(width * done / std::max<size_t>(total_, 1));
        std::fprintf(stderr, "\r[%s%s] %zu/%zu, %s elapsed, %s left  %-50.50s", std::string(filled, '#').c_str(),
                     std::string(width - filled, ' ').c_str(), done, total_, duration(elapsed).c_str(),
                     done ? ("~" + duration(left)).c_str() : "?", what.c_str());
        std::fflush(stderr);
    }

private:
    size_t total_;
    std::chrono::steady_clock::time_point start_;
    bool open_ = false;
};

std::vector<double> loadOrRenderReference(const SceneDesc& scene, const MeshData& mesh, VkExtent2D size,
                                          const fs::path& cache, const std::function<void(double)>& progress) {
    if (fs::exists(cache)) {
        const FloatImage img = readExr(cache.string());
        if (img.width == size.width && img.height == size.height) {
            std::vector<double> rgb(size_t{size.width} * size.height * 3);
            for (size_t p = 0; p < rgb.size() / 3; ++p)
                for (size_t c = 0; c < 3; ++c) rgb[p * 3 + c] = img.rgba[p * 4 + c];
            return rgb;
        }
    }
    const reference::ReferenceImage ref = reference::renderReference(scene, mesh, size.width, size.height, {}, progress);
    std::vector<float> rgba(size_t{size.width} * size.height * 4, 1.0f);
    for (size_t p = 0; p < rgba.size() / 4; ++p)
        for (size_t c = 0; c < 3; ++c) rgba[p * 4 + c] = static_cast<float>(ref.rgb[p * 3 + c]);
    writeExr(cache.string(), size.width, size.height, rgba);
    return ref.rgb;
}

const char* kCsvHeader =
    "scene,label,family,method,profile,width,height,slices,samples,initialStep,minMaxTrees,"
    "shadowMap,frames,medianMs,p10Ms,p90Ms,minMs,maxMs,meanRelativeError,rmse,p99Error,maxError,"
    "fractionOver5pct,psnrDb,nonFinite,device,cpuDevice,cpuWorkMs,occluders,lights";

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
    for (const fs::path& dir : {out / "strips", out / "references"}) {
        std::error_code ec;
        fs::create_directories(dir, ec);
        if (ec) throw std::runtime_error("--out " + out.string() + ": cannot create " + dir.string() + ": " + ec.message());
    }
    { TempFile probe((out / "bench.json").string(), "--out"); }  // the folder is writable

    Activity benchmarking("benchmarking " + configPath);
    rg::Device device(deviceOptions);
    std::ofstream csv(out / "bench.csv");
    if (!csv) throw std::runtime_error((out / "bench.csv").string() + ": cannot open for writing");
    csv << kCsvHeader << "\n" << std::flush;
    nlohmann::json all = nlohmann::json::array();
    Progress progress(config.runs.size());

    std::map<std::string, std::vector<double>> references;
    std::unique_ptr<EngineRenderer> renderer;
    std::string rendererKey;
    size_t done = 0;
    for (const bench::BenchRun& run : config.runs) {
        const std::string what = fs::path(run.scene).stem().string() + ": " + run.label;
        progress.show(done, what);
        auto& [scene, mesh] = scenes.at(run.scene);
        // Seed 001's closed form takes unshadowed point and spot lights only; elsewhere there is
        // nothing to measure.
        const bool unshadowedPointLike = scene.light.type == LightKind::Point ||
                                         (scene.light.type == LightKind::Spot && scene.light.shadowMapSize == 0);
        if (run.method == lightscatter::Method::Analytic && !unshadowedPointLike) {
            ++done;
            continue;
        }
        // Seed 004's beam tree is built from a point or spot light.
        if ((run.method == lightscatter::Method::BeamTreeAnalytic ||
             run.method == lightscatter::Method::BeamTreeSampling) &&
            scene.light.type == LightKind::Directional) {
            ++done;
            continue;
        }
        SceneDesc sceneForRun = scene;
        if (run.shadowMapSize) sceneForRun.light.shadowMapSize = run.shadowMapSize;
        const std::string key = run.scene + "/" + std::to_string(run.size.width) + "x" +
                                std::to_string(run.size.height) + "/" + std::to_string(sceneForRun.light.shadowMapSize);
        if (key != rendererKey) {
            renderer.reset();
            renderer = std::make_unique<EngineRenderer>(device, sceneForRun, mesh, run.size);
            rendererKey = key;
        }
        RenderOptions options;
        options.method = run.method;
        options.profile = run.custom ? lightscatter::Profile::Custom : run.profile;
        if (run.custom) options.custom = run.settings;
        const lightscatter::Settings used = run.custom ? run.settings : lightscatter::profileSettings(run.profile);

        for (int i = 0; i < config.warmup; ++i) renderer->render(options);
        std::vector<double> totals, cpuTotals;
        std::map<std::string, std::vector<double>> perPass, perCpuWork;
        FrameOutput last;
        for (int i = 0; i < config.frames; ++i) {
            last = renderer->render(options);
            totals.push_back(last.plugin.totalMilliseconds);
            for (const auto& p : last.plugin.passes) perPass[p.name].push_back(p.milliseconds);
            double cpu = 0.0;
            for (const auto& w : last.plugin.cpuWork) {
                perCpuWork[w.name].push_back(w.milliseconds);
                cpu += w.milliseconds;
            }
            cpuTotals.push_back(cpu);
        }
        const bench::Spread t = bench::spreadOf(totals);
        const bench::Spread cpu = bench::spreadOf(cpuTotals);

        nlohmann::json row;
        row["scene"] = fs::path(run.scene).stem().string();
        row["label"] = run.label;
        row["family"] = run.family;
        row["method"] = lightscatter::methodName(run.method);
        row["methodRan"] = last.plugin.method;  // with auto, the method it picked
        row["coneSamples"] = used.coneSamples;
        row["coneLimited"] = used.coneLimited;
        row["shadowSampling"] = used.shadowSampling;
        row["lightModel"] =
            used.lightModel == lightscatter::LightModel::Simplified ? "simplified" : "full";
        row["profile"] = run.custom ? "custom" : lightscatter::profileName(run.profile);
        row["size"] = {run.size.width, run.size.height};
        row["slices"] = used.slices;
        row["samples"] = used.samplesPerSlice;
        row["initialStep"] = used.initialSampleStep;
        row["minMaxTrees"] = used.minMaxTrees;
        row["shadowMapSize"] = sceneForRun.light.shadowMapSize;
        row["frames"] = config.frames;
        row["time"] = {{"median", t.median}, {"p10", t.p10}, {"p90", t.p90}, {"min", t.min}, {"max", t.max}};
        nlohmann::json passes = nlohmann::json::array();
        for (const auto& p : last.plugin.passes) {
            const bench::Spread s = bench::spreadOf(perPass[p.name]);
            passes.push_back({{"name", p.name}, {"median", s.median}, {"p10", s.p10}, {"p90", s.p90}});
        }
        row["passes"] = passes;
        // The plugin's CPU work per frame (the beam tree), outside the GPU time above.
        row["cpuTime"] = {{"median", cpu.median}, {"p10", cpu.p10}, {"p90", cpu.p90}, {"min", cpu.min},
                          {"max", cpu.max}};
        nlohmann::json cpuWork = nlohmann::json::array();
        for (const auto& w : last.plugin.cpuWork) {
            const bench::Spread s = bench::spreadOf(perCpuWork[w.name]);
            cpuWork.push_back({{"name", w.name}, {"median", s.median}, {"p10", s.p10}, {"p90", s.p90}});
        }
        row["cpuWork"] = cpuWork;
        row["occluders"] = renderer->occluderCount();
        row["lights"] = scene.lightCount();
        row["device"] = device.name();
        row["driver"] = device.driverName();
        row["cpuDevice"] = device.isCpu();

        std::string errorColumns = ",,,,,,";
        size_t nonFinite = 0;
        for (float v : last.inscatter) nonFinite += std::isfinite(v) ? 0 : 1;
        if (run.measureError) {
            const std::string refKey = run.scene;
            if (!references.count(refKey)) {
                // Keyed by the scene file's contents too, so an edited scene is never judged against
                // the reference of its earlier version.
                const std::string text = readInputFile(run.scene, "scene file", 16 * kMiB);
                char hash[32];
                std::snprintf(hash, sizeof hash, "%016zx", std::hash<std::string>{}(text));
                const fs::path cache = out / "references" /
                                       (fileSafe(fs::path(run.scene).stem().string()) + "_" +
                                        std::to_string(run.size.width) + "x" + std::to_string(run.size.height) + "_" +
                                        hash + ".exr");
                int shown = -1;
                references[refKey] = loadOrRenderReference(scene, mesh, run.size, cache, [&](double f) {
                    const int percent = static_cast<int>(f * 100);
                    if (percent / 10 == shown / 10) return;  // a line every 10%, not every row
                    shown = percent;
                    progress.show(done, what + " (reference " + std::to_string(percent) + "%)");
                });
            }
            const bench::ErrorMetrics e = bench::compareToReference(last.inscatter, references[refKey], scene.exposure);
            nonFinite = e.nonFinite;
            row["error"] = {{"meanRelative", e.meanRelative}, {"rmse", e.rmse}, {"p99", e.p99}, {"max", e.max},
                            {"fractionOver5pct", e.fractionOver}, {"psnrDb", e.psnr}};
            char buf[256];
            std::snprintf(buf, sizeof buf, "%.6g,%.6g,%.6g,%.6g,%.6g,%.3f", e.meanRelative, e.rmse, e.p99, e.max,
                          e.fractionOver, e.psnr);
            errorColumns = buf;
            bench::writeStrip((out / "strips" / (fileSafe(row["scene"].get<std::string>() + "_" + run.label) + ".png")).string(),
                              run.size.width, run.size.height, references[refKey], last.inscatter, scene.exposure);
        }
        row["nonFinite"] = nonFinite;
        char line[1024];
        std::snprintf(line, sizeof line,
                      "%s,%s,%s,%s,%s,%u,%u,%u,%u,%u,%d,%u,%d,"
                      "%.6f,%.6f,%.6f,%.6f,%.6f,%s,%zu,\"%s\",%d,%.6f,%zu,%zu",
                      row["scene"].get<std::string>().c_str(), run.label.c_str(),
                      run.family.c_str(), lightscatter::methodName(run.method),
                      row["profile"].get<std::string>().c_str(), run.size.width, run.size.height,
                      used.slices, used.samplesPerSlice, used.initialSampleStep,
                      used.minMaxTrees ? 1 : 0, sceneForRun.light.shadowMapSize, config.frames,
                      t.median, t.p10, t.p90, t.min, t.max, errorColumns.c_str(), nonFinite,
                      device.name().c_str(), device.isCpu() ? 1 : 0, cpu.median,
                      renderer->occluderCount(), scene.lightCount());
        csv << line << "\n" << std::flush;
        all.push_back(row);
        writeTextFile((out / "bench.json").string(),
                      nlohmann::json{{"config", config.name}, {"runs", all}}.dump(2) + "\n");
        ++done;
    }
    progress.show(done, "done");
    progress.finish();
    std::cout << "wrote " << (out / "bench.csv").string() << ", bench.json and " << done << " runs' strips ("
              << device.name() << (device.isCpu() ? ", CPU timings" : "") << ")\n";
    return device.messageCount() > 0 ? 3 : 0;
}

}  // namespace host
