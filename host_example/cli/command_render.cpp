// lightscatter render SCENE.json [--out FILE.png|.exr] [--inscatter FILE.exr] [--method NAME]
//   [--profile NAME] [--settings FILE.json] [--size WxH] [--timings FILE.json] [--frames N]
//   [--count-steps]
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "activity.h"
#include "command_options.h"
#include "commands.h"
#include "image_io.h"
#include "output_set.h"
#include "progress_line.h"
#include "scene_inputs.h"
#include "tonemap.h"

namespace host {
namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Epipolar's ray-march steps (DebugOptions::countSteps), as counted and per ray-marching sample.
nlohmann::json stepsJson(const lightscatter::StepCounts& s) {
    const double n = s.samples > 0 ? static_cast<double>(s.samples) : 1.0;
    return {
        {"samples", s.samples},
        {"rays", s.rays},
        {"lineSteps", s.lineSteps},
        {"treeNodes", s.treeNodes},
        {"degenerateRays", s.degenerateRays},
        {"degenerateSteps", s.degenerateSteps},
        {"listedSamples", s.listedSamples},
        {"unbuiltTreeNodes", s.unbuiltTreeNodes},
        {"stepsPerSample", static_cast<double>(s.lineSteps + s.degenerateSteps) / n},
        {"nodesPerSample", static_cast<double>(s.treeNodes) / n},
        {"degenerateShare",
         s.rays > 0 ? static_cast<double>(s.degenerateRays) / static_cast<double>(s.rays) : 0.0}};
}

nlohmann::json timingsJson(const rg::Device& device, const SceneOptions& o, VkExtent2D size,
                           const FrameOutput& f, int frames) {
    nlohmann::json j;
    j["device"] = device.name();
    j["driver"] = device.driverName();
    j["cpuDevice"] = device.isCpu();  // lavapipe: CPU timings, not GPU ones
    j["method"] = lightscatter::methodName(o.render.method);
    j["methodRan"] = f.plugin.method;  // with auto, the method it picked
    j["reason"] = f.plugin.reason;
    j["notice"] = f.plugin.notice;
    // Each light's method and why (FrameReport::lights).
    nlohmann::json lights = nlohmann::json::array();
    for (const auto& l : f.plugin.lights)
        lights.push_back({{"method", l.method}, {"reason", l.reason}, {"notice", l.notice}});
    j["lights"] = lights;
    j["profile"] = lightscatter::profileName(o.render.profile);
    j["size"] = {size.width, size.height};
    j["frames"] = frames;
    j["depthStencilFormat"] = f.plugin.depthStencilFormat;
    j["linOut"] = o.render.linOut;  // whether the frame also wrote Lin alone (--inscatter)
    nlohmann::json passes = nlohmann::json::array();
    for (const auto& p : f.plugin.passes)
        passes.push_back({{"name", p.name}, {"milliseconds", p.milliseconds}});
    j["passes"] = passes;
    j["totalMilliseconds"] = f.plugin.totalMilliseconds;
    nlohmann::json engine = nlohmann::json::array();
    for (const auto& p : f.engine.passes)
        engine.push_back({{"name", p.name}, {"milliseconds", p.milliseconds}});
    j["engine"] = {{"passes", engine}, {"totalMilliseconds", f.engine.totalMilliseconds}};
    if (f.plugin.steps) j["steps"] = stepsJson(*f.plugin.steps);
    return j;
}

}  // namespace

int runRender(Args& args) {
    std::string out = args.take("--out", "");
    const std::string inscatter = args.take("--inscatter", "");
    const std::string timings = args.take("--timings", "");
    const int frames = parseCount(args.take("--frames", "1"), "--frames");
    const bool countSteps = args.flag("--count-steps");
    SceneOptions o = takeSceneOptions(args, nullptr);
    o.render.countSteps = countSteps;
    // Lin alone only for --inscatter: the frame is then what an engine that composites asks for.
    o.render.linOut = !inscatter.empty();
    const std::string scenePath = args.positional("SCENE.json");
    args.finish();
    if (out.empty()) out = std::filesystem::path(scenePath).stem().string() + ".png";
    if (!endsWith(out, ".png") && !endsWith(out, ".exr"))
        throw std::runtime_error("--out " + out + ": must end in .png or .exr");
    if (!inscatter.empty() && !endsWith(inscatter, ".exr"))
        throw std::runtime_error("--inscatter " + inscatter + ": must end in .exr");

    // A render can take a minute (brute force at 2560x1600 on a CPU device): past 2 s a line on
    // the terminal says what it is doing.
    std::optional<ProgressLine> progress(std::in_place, "loading " + scenePath);
    const SceneDesc scene = loadSceneFile(scenePath);  // scene errors before any device
    const MeshData mesh = loadSceneMeshes(scene);
    for (const auto& w : mesh.warnings) std::cerr << "lightscatter: warning: " << w << "\n";
    const VkExtent2D size = sceneSize(o, {960, 540});

    // Every output is checked, and a temporary made beside it, before anything renders.
    OutputSet outputs;
    addSceneInputs(outputs, scenePath, scene, mesh, "the scene");
    if (!o.settingsPath.empty()) outputs.addInput("the settings file", o.settingsPath);
    outputs.add("--out", out);
    if (!inscatter.empty()) outputs.add("--inscatter", inscatter);
    if (!timings.empty()) outputs.add("--timings", timings);

    Activity rendering("rendering " + scenePath + " at " + std::to_string(size.width) + "x" +
                       std::to_string(size.height));
    progress->phase("opening the device, uploading the scene");
    rg::Device device(o.device);
    EngineRenderer renderer(device, scene, mesh, size);
    FrameOutput frame;
    for (int i = 0; i < frames; ++i) {
        progress->phase("rendering frame " + std::to_string(i + 1) + " of " +
                        std::to_string(frames) +
                        ": shadow maps, the scene, then the plugin's passes");
        frame = renderer.render(o.render);
    }
    progress->phase("writing " + out);

    Activity writing("writing " + out);
    if (endsWith(out, ".png")) {
        const std::vector<uint8_t> pixels = toneMap(frame.color, scene.exposure);
        outputs.write(out, encodePng(size.width, size.height, pixels), "PNG");
    } else {
        outputs.write(out, encodeExr(size.width, size.height, frame.color), "OpenEXR");
    }
    if (!inscatter.empty())
        outputs.write(inscatter, encodeExr(size.width, size.height, frame.inscatter), "OpenEXR");
    if (!timings.empty())
        outputs.writeText(timings, timingsJson(device, o, size, frame, frames).dump(2) + "\n");
    outputs.commit();
    progress.reset();  // cleared before the summary

    if (!frame.plugin.notice.empty())
        std::cerr << "lightscatter: notice: " << frame.plugin.notice << "\n";
    const std::string method =
        o.render.method == lightscatter::Method::Auto
            ? "auto -> " + frame.plugin.method + " (" + frame.plugin.reason + ")"
            : std::string(lightscatter::methodName(o.render.method));
    std::printf("%s: %ux%u, %s, %s, %s on '%s'%s: plugin %.3f ms, engine %.3f ms\n", out.c_str(),
                size.width, size.height, method.c_str(),
                lightscatter::profileName(o.render.profile),
                frame.plugin.passNames.empty() ? "-" : "rendered", device.name().c_str(),
                device.isCpu() ? " (CPU timings)" : "", frame.plugin.totalMilliseconds,
                frame.engine.totalMilliseconds);
    // A frame of several lights: each light's method, and with auto why.
    if (frame.plugin.lights.size() > 1)
        for (size_t i = 0; i < frame.plugin.lights.size(); ++i) {
            const auto& l = frame.plugin.lights[i];
            std::printf(
                "  lights[%zu]: %s%s%s\n", i, l.method.c_str(),
                o.render.method == lightscatter::Method::Auto ? " (" : "",
                o.render.method == lightscatter::Method::Auto ? (l.reason + ")").c_str() : "");
        }
    if (countSteps) {
        if (frame.plugin.steps) {
            const nlohmann::json j = stepsJson(*frame.plugin.steps);
            std::printf("ray-march steps: %s\n", j.dump().c_str());
        } else {
            std::printf("ray-march steps: none counted (%s ran no epipolar ray march)\n",
                        frame.plugin.method.c_str());
        }
    }
    if (device.messageCount() > 0) {
        std::cerr << "lightscatter: the validation layer reported " << device.messageCount()
                  << " message(s)\n";
        return 3;
    }
    return 0;
}

}  // namespace host
