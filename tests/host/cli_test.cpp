// Each command of the lightscatter command line end to end, on lavapipe with validation, and every
// failure path: one line naming the file, field or value, a non-zero exit, no file half-written.
#include <gtest/gtest.h>
#include <algorithm>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "cli_runner.h"
#include "image_io.h"

using cli_test::exists;
using cli_test::expectFailure;
using cli_test::path;
using cli_test::run;
using cli_test::scene;
using cli_test::writeFile;

TEST(Cli, RenderWritesPngLinAndTimings) {
    const auto r =
        run("render " + scene("atrium") +
            " --size 64x36 --out atrium.png --inscatter lin.exr --timings t.json --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_TRUE(exists("atrium.png"));
    const host::FloatImage lin = host::readExr(path("lin.exr"));
    EXPECT_EQ(lin.width, 64u);
    EXPECT_EQ(lin.height, 36u);
    float most = 0;
    for (size_t i = 0; i < lin.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        ASSERT_TRUE(std::isfinite(lin.rgba[i]));
        EXPECT_GE(lin.rgba[i], 0.0f);
        most = std::max(most, lin.rgba[i]);
    }
    EXPECT_GT(most, 0.0f);
    std::ifstream t(path("t.json"));
    const auto j = nlohmann::json::parse(t);
    EXPECT_FALSE(j["device"].get<std::string>().empty());
    // auto is the default: on a 64x36 screen a shadowed light is marched per pixel.
    EXPECT_EQ(j["method"], "auto");
    EXPECT_EQ(j["methodRan"], "brute-force");
    EXPECT_NE(j["reason"].get<std::string>().find("per-pixel marching is cheaper"),
              std::string::npos)
        << j["reason"];
    EXPECT_GE(j["passes"].size(), 3u);  // constants, brute-force march, composite
    EXPECT_GT(j["totalMilliseconds"].get<double>(), 0.0);
}

// Without --inscatter the frame asks for no Lin (an engine's frame, the one --timings measures);
// the color is the same bits either way.
TEST(Cli, RenderWithoutInscatterAsksForNoLinAndGivesTheSameColor) {
    for (const char* method : {"epipolar", "brute-force"}) {
        const std::string common =
            "render " + scene("atrium") + " --size 64x36 --method " + std::string(method);
        const auto with =
            run(common + " --out with.exr --inscatter lin.exr --timings with.json --validation");
        ASSERT_EQ(with.exitCode, 0) << method << ": " << with.out;
        const auto without = run(common + " --out without.exr --timings without.json --validation");
        ASSERT_EQ(without.exitCode, 0) << method << ": " << without.out;
        const host::FloatImage a = host::readExr(path("with.exr"));
        const host::FloatImage b = host::readExr(path("without.exr"));
        ASSERT_EQ(a.rgba.size(), b.rgba.size());
        EXPECT_TRUE(std::equal(a.rgba.begin(), a.rgba.end(), b.rgba.begin())) << method;
        std::ifstream ta(path("with.json")), tb(path("without.json"));
        EXPECT_EQ(nlohmann::json::parse(ta)["linOut"], true) << method;
        EXPECT_EQ(nlohmann::json::parse(tb)["linOut"], false) << method;
    }
}

// A sun and two spots ("lights") in one frame: epipolar and brute force, Lin summed into
// --inscatter.
TEST(Cli, RenderASunAndTwoSpots) {
    for (const char* method : {"epipolar", "brute-force", "auto"}) {
        const auto r =
            run("render " + scene("atrium_lights") + " --size 48x27 --method " + method +
                " --out lights.png --inscatter lights.exr --timings lights.json --validation");
        ASSERT_EQ(r.exitCode, 0) << method << ": " << r.out;
        std::ifstream t(path("lights.json"));
        const auto j = nlohmann::json::parse(t);
        EXPECT_NE(j["reason"].get<std::string>().find("3 lights"), std::string::npos)
            << j["reason"];
        const host::FloatImage lin = host::readExr(path("lights.exr"));
        float most = 0;
        for (size_t i = 0; i < lin.rgba.size(); ++i)
            if (i % 4 != 3) most = std::max(most, lin.rgba[i]);
        EXPECT_GT(most, 0.0f);
    }
    // A method that cannot honour one of the lights refuses the frame, naming the light.
    const auto analytic =
        run("render " + scene("atrium_lights") + " --size 48x27 --method analytic --out s.png");
    EXPECT_NE(analytic.exitCode, 0);
    EXPECT_NE(analytic.out.find("lights[0]: method analytic"), std::string::npos) << analytic.out;
}

// --count-steps: epipolar's ray-march steps printed and in --timings (a frame of three lights sums
// its chains'); a method without that march counts nothing.
TEST(Cli, RenderCountsTheRayMarchSteps) {
    for (const char* name : {"window_room", "atrium_lights"}) {
        const auto r = run("render " + scene(name) +
                           " --size 64x36 --method epipolar --count-steps --out s.png --timings "
                           "s.json --validation");
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.out;
        EXPECT_NE(r.out.find("ray-march steps: {"), std::string::npos) << r.out;
        std::ifstream t(path("s.json"));
        const auto steps = nlohmann::json::parse(t)["steps"];
        ASSERT_TRUE(steps.is_object()) << name;
        EXPECT_GT(steps["samples"].get<uint64_t>(), 0u) << name;
        EXPECT_GT(steps["rays"].get<uint64_t>(), 0u) << name;
        EXPECT_GT(steps["lineSteps"].get<uint64_t>(), 0u) << name;
        EXPECT_GT(steps["treeNodes"].get<uint64_t>(), 0u) << name;  // the profile's trees are on
        EXPECT_GT(steps["stepsPerSample"].get<double>(), 0.0) << name;
    }
    const auto brute =
        run("render " + scene("window_room") +
            " --size 64x36 --method brute-force --count-steps --out b.png --timings b.json");
    ASSERT_EQ(brute.exitCode, 0) << brute.out;
    EXPECT_NE(brute.out.find("ray-march steps: none counted"), std::string::npos) << brute.out;
    std::ifstream t(path("b.json"));
    EXPECT_FALSE(nlohmann::json::parse(t).contains("steps"));
}

TEST(Cli, RenderEachSceneWithEachMethod) {
    for (const char* name : {"atrium", "window_room", "engine_spot", "point_fog"})
        for (const char* method : {"epipolar", "brute-force", "cone-march", "planes", "froxels",
                                   "froxels-unreal", "auto"}) {
            const auto r = run(std::string("render ") + scene(name) + " --size 48x27 --method " +
                               method + " --out " + name + ".exr --validation");
            EXPECT_EQ(r.exitCode, 0) << name << " " << method << ": " << r.out;
            EXPECT_TRUE(exists(std::string(name) + ".exr")) << name;
        }
    // analytic is seed 001's closed form: the unshadowed point light only; one line elsewhere.
    const auto point = run("render " + scene("point_fog") +
                           " --size 48x27 --method analytic --out p.exr --validation");
    EXPECT_EQ(point.exitCode, 0) << point.out;
    // The plugin refuses once the engine has its device, so the device's line comes first.
    auto refusedAfterDevice = [](const cli_test::Result& r, const std::string& fragment) {
        EXPECT_NE(r.exitCode, 0) << r.out;
        const size_t device = r.out.find("using Vulkan device");
        const std::string rest =
            r.out.substr(device == std::string::npos ? 0 : r.out.find('\n', device) + 1);
        EXPECT_NE(rest.find(fragment), std::string::npos) << r.out;
        EXPECT_EQ(std::count(rest.begin(), rest.end(), '\n'), 1) << r.out;
    };
    refusedAfterDevice(
        run("render " + scene("atrium") + " --size 48x27 --method analytic --out a.exr"),
        "light is directional");
    refusedAfterDevice(
        run("render " + scene("window_room") + " --size 48x27 --method analytic --out w.exr"),
        "cannot cast shadows");
}

// Seed 002's planes through the command line: an image, Lin, and timings naming the method.
TEST(Cli, RenderWithPlanesWritesAnImage) {
    const auto r = run("render " + scene("window_room") +
                       " --size 48x27 --method planes --out planes.png --inscatter planes.exr"
                       " --timings planes.json --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("planes"), std::string::npos) << r.out;
    EXPECT_TRUE(exists("planes.png"));
    const host::FloatImage lin = host::readExr(path("planes.exr"));
    ASSERT_EQ(lin.width, 48u);
    ASSERT_EQ(lin.height, 27u);
    float most = 0;
    for (size_t i = 0; i < lin.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        ASSERT_TRUE(std::isfinite(lin.rgba[i]));
        EXPECT_GE(lin.rgba[i], 0.0f);
        most = std::max(most, lin.rgba[i]);
    }
    EXPECT_GT(most, 0.0f);
    std::ifstream t(path("planes.json"));
    const auto j = nlohmann::json::parse(t);
    EXPECT_EQ(j["method"], "planes");
    EXPECT_EQ(j["methodRan"], "planes");
}

// "slices", the planes method's former name, and the former names of its settings still work
// wherever a user may have written them: --method (render, budget) and --settings; what is
// printed names the method "planes". A settings file giving one field under both names is
// refused in one line naming both.
TEST(Cli, FormerNamesOfThePlanesMethodAndItsSettingsStillWork) {
    const auto r = run("render " + scene("window_room") +
                       " --size 48x27 --method slices --out s.png --timings s.json --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::ifstream t(path("s.json"));
    const auto j = nlohmann::json::parse(t);
    EXPECT_EQ(j["method"], "planes");
    EXPECT_EQ(j["methodRan"], "planes");

    writeFile("former.json", R"({"slicePlanes": 24, "sliceTarget": "rgba8",
        "slicePlaneScaling": true, "sliceRange": 0, "sliceDither": false, "sliceBlur": 1,
        "sliceAmbient": 0.001})");
    writeFile("current.json", R"({"planeCount": 24, "planeTarget": "rgba8",
        "planeScaling": true, "planeRange": 0, "planeDither": false, "planeBlur": 1,
        "planeAmbient": 0.001})");
    const auto former = run("budget --method slices --settings former.json --json");
    const auto current = run("budget --method planes --settings current.json --json");
    ASSERT_EQ(former.exitCode, 0) << former.out;
    ASSERT_EQ(current.exitCode, 0) << current.out;
    EXPECT_EQ(former.out, current.out);
    const auto parsed = nlohmann::json::parse(former.out);
    EXPECT_EQ(parsed[0]["method"], "planes");
    EXPECT_EQ(parsed[0]["settings"]["planes.count"], 24);
    EXPECT_EQ(parsed[0]["settings"]["planes.target"], "rgba8");
    const auto text = run("budget --method slices --profile balanced");
    ASSERT_EQ(text.exitCode, 0) << text.out;
    EXPECT_NE(text.out.find("planes, balanced: planes.count 128, planes.target float16"),
              std::string::npos)
        << text.out;

    writeFile("both.json", R"({"planeBlur": 1, "sliceBlur": 2})");
    expectFailure(run("render " + scene("window_room") + " --method planes --settings both.json"),
                  "both.json: planeBlur and sliceBlur are one field (planes.blur): give it once");
    // The plugin's rules name the field as the file gave it.
    writeFile("few.json", R"({"slicePlanes": 1})");
    expectFailure(run("budget --method planes --settings few.json"),
                  "few.json: slicePlanes = 1: must be in [2, 4096]");
}

// Every planes field of --settings by name; the noise makes auto pick planes, and is refused in
// one line, before any device, with a method that does not sample it.
TEST(Cli, PlanesSettingsAndTheirNoise) {
    writeFile("planes-settings.json", R"({"planeCount": 24, "planeTarget": "rgba8",
        "planeScaling": true, "planeRange": 0, "planeDither": false, "planeBlur": 1,
        "planeAmbient": 0.001, "noiseAmplitude": 0.5, "noiseScale": 2,
        "noiseVelocity": [0.1, 0, -0.1, 0.2]})");
    const auto r = run("render " + scene("window_room") +
                       " --size 48x27 --settings planes-settings.json --out n.png --timings n.json"
                       " --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::ifstream t(path("n.json"));
    const auto j = nlohmann::json::parse(t);
    EXPECT_EQ(j["profile"], "custom");
    EXPECT_EQ(j["method"], "auto");
    EXPECT_EQ(j["methodRan"], "planes");
    EXPECT_NE(j["reason"].get<std::string>().find("noise"), std::string::npos) << j["reason"];

    const auto refused = run("render " + scene("window_room") +
                             " --size 48x27 --method cone-march --settings planes-settings.json"
                             " --out c.png");
    expectFailure(refused,
                  "planes-settings.json: noiseAmplitude = 0.5: seed 002's scrolling noise "
                  "is honoured by planes only; --method cone-march");
    EXPECT_EQ(refused.out.find("using Vulkan device"), std::string::npos) << refused.out;
    expectFailure(run("graph " + scene("atrium") +
                      " --json --method epipolar --settings planes-settings.json"),
                  "noiseAmplitude");
    EXPECT_FALSE(exists("c.png"));

    writeFile("target.json", R"({"planeTarget": "rgba16"})");
    expectFailure(run("render " + scene("window_room") + " --method planes --settings target.json"),
                  "target.json: planeTarget = \"rgba16\": must be one of float16, float32, rgba8");
    writeFile("amplitude.json", R"({"noiseAmplitude": 2})");
    expectFailure(
        run("render " + scene("window_room") + " --method planes --settings amplitude.json"),
        "amplitude.json: noiseAmplitude = 2: must be in [0, 1]");
    writeFile("velocity.json", R"({"noiseVelocity": [1, 2, 3]})");
    expectFailure(run("view " + scene("window_room") + " --method planes --settings velocity.json"),
                  "velocity.json: noiseVelocity = [1,2,3]: must be an array of 4 numbers");
    writeFile("planes.json", R"({"planeCount": 1})");
    expectFailure(run("budget --method planes --settings planes.json"),
                  "planes.json: planeCount = 1: must be in [2, 4096]");
}

// Seed 004's simplified light model by --settings: beam-tree-analytic honours it; a method that
// does not is refused in one line, before any device.
TEST(Cli, SimplifiedLightModelSettings) {
    writeFile("simplified.json",
              R"({"lightModel": "simplified", "simplifiedA0": 0.01, "simplifiedA1": 1})");
    const auto r =
        run("render " + scene("point_fog") +
            " --size 48x27 --method beam-tree-analytic --settings simplified.json --out s.png"
            " --timings s.json --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::ifstream t(path("s.json"));
    const auto j = nlohmann::json::parse(t);
    EXPECT_EQ(j["methodRan"], "beam-tree-analytic");

    const auto refused =
        run("render " + scene("point_fog") +
            " --size 48x27 --method epipolar --settings simplified.json --out e.png");
    expectFailure(
        refused,
        "simplified.json: lightModel = \"simplified\": seed 004's simplified light model is "
        "honoured by analytic and beam-tree-analytic only; --method epipolar");
    EXPECT_EQ(refused.out.find("using Vulkan device"), std::string::npos) << refused.out;
    EXPECT_FALSE(exists("e.png"));
    writeFile("a1.json", R"({"lightModel": "simplified", "simplifiedA1": -2})");
    expectFailure(
        run("render " + scene("point_fog") + " --method beam-tree-analytic --settings a1.json"),
        "a1.json: simplifiedA1 = -2: must be in [0.001, 1000]");
}

TEST(Cli, BudgetOfPlanesPrintsTheirTextures) {
    const auto r = run("budget --method planes");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    for (const char* line : {"planes, high-quality: planes.count 256, planes.target float32",
                             "planes, balanced: planes.count 128, planes.target float16",
                             "planes, high-performance: planes.count 100, planes.target rgba8",
                             "planes, low-high-performance: planes.count 48, planes.target rgba8"})
        EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
    EXPECT_NE(r.out.find("R32G32B32A32_SFLOAT"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("R8G8B8A8_UNORM"), std::string::npos) << r.out;
    // Seed 000's figures are the epipolar method's, and no epipolar texture is listed.
    EXPECT_EQ(r.out.find("seed 000"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("epipolar"), std::string::npos) << r.out;

    const auto j = run("budget --method planes --profile high-performance --size 320x180 --json");
    ASSERT_EQ(j.exitCode, 0) << j.out;
    const auto parsed = nlohmann::json::parse(j.out);
    ASSERT_EQ(parsed.size(), 1u);
    EXPECT_EQ(parsed[0]["method"], "planes");
    EXPECT_EQ(parsed[0]["settings"]["planes.count"], 100);
    EXPECT_EQ(parsed[0]["settings"]["planes.target"], "rgba8");
    EXPECT_FALSE(parsed[0].contains("seed"));
    bool rgba8 = false;
    for (const auto& e : parsed[0]["resources"]) rgba8 |= e["format"] == "R8G8B8A8_UNORM";
    EXPECT_TRUE(rgba8) << parsed.dump();
    const auto e = run("budget --profile balanced --json");
    ASSERT_EQ(e.exitCode, 0) << e.out;
    EXPECT_EQ(nlohmann::json::parse(e.out)[0]["method"], "epipolar");

    // Any method has a budget: one whose textures do not follow the profile lists its own.
    const auto cone = run("budget --method cone-march --profile balanced --json");
    ASSERT_EQ(cone.exitCode, 0) << cone.out;
    EXPECT_EQ(nlohmann::json::parse(cone.out)[0]["settings"]["coneMarch.samples"], 32);
    expectFailure(run("budget --method raytrace"), "unknown method 'raytrace'");
}

// The froxel grid's two textures at each preset: HDRP's 240x135x64 at 1920x1080 (float32
// in-scattering, 32 MiB with the offline estimate's rounding; float16 integrated, 16 MiB), and
// Unreal's 120x68x64, a quarter of it.
TEST(Cli, BudgetOfFroxelsFollowsThePreset) {
    auto grid = [](const std::string& preset) {
        const auto r = run("budget --method " + preset + " --profile balanced --size 1920x1080 " +
                           "--lights sun,spot --json");
        EXPECT_EQ(r.exitCode, 0) << r.out;
        const auto j = nlohmann::json::parse(r.out).at(0);
        EXPECT_EQ(j["method"], "froxels");
        EXPECT_EQ(j["lightMethods"], nlohmann::json({"froxels", "froxels"}));
        std::map<std::string, nlohmann::json> byName;
        for (const auto& e : j["resources"]) byName[e["name"]] = e;
        return byName;
    };
    for (const auto& [preset, columns, rows] : {std::tuple{"froxels", 240, 135},
                                                {"froxels-hdrp", 240, 135},
                                                {"froxels-unreal", 120, 68}}) {
        auto g = grid(preset);
        for (const char* name : {"froxel in-scattering", "froxel integrated in-scattering"}) {
            ASSERT_TRUE(g.count(name)) << preset << ": " << name;
            EXPECT_EQ(g[name]["width"], columns) << preset;
            EXPECT_EQ(g[name]["height"], rows) << preset;
            EXPECT_EQ(g[name]["depth"], 64) << preset;
        }
        EXPECT_EQ(g["froxel in-scattering"]["format"], "R32G32B32A32_SFLOAT");
        EXPECT_EQ(g["froxel integrated in-scattering"]["format"], "R16G16B16A16_SFLOAT");
        EXPECT_GE(g["froxel in-scattering"]["bytes"].get<uint64_t>(),
                  uint64_t(columns) * rows * 64 * 16);
    }
    // The temporal mode keeps two float32 grids across frames.
    const auto t =
        run("budget --method froxels-unreal-temporal --profile balanced --size 1920x1080");
    ASSERT_EQ(t.exitCode, 0) << t.out;
    for (const char* line : {"froxel history", "froxel history (next)", "120 x 68    x 64",
                             "(kept across frames)", "froxels.slices 64", "froxels.temporal true"})
        EXPECT_NE(t.out.find(line), std::string::npos) << line << "\n" << t.out;
    EXPECT_EQ(t.out.find("froxel pixel history"), std::string::npos) << t.out;
    // ... and with "-pixels", two screen-sized float32 images more: its still frames per pixel.
    const auto px =
        run("budget --method froxels-unreal-pixels --profile balanced --size 1920x1080");
    ASSERT_EQ(px.exitCode, 0) << px.out;
    for (const char* line :
         {"froxel history (next)", "froxels.temporal true", "froxels.pixelHistory true"})
        EXPECT_NE(px.out.find(line), std::string::npos) << line << "\n" << px.out;
    const size_t at = px.out.find("froxel pixel history (next)");
    ASSERT_NE(at, std::string::npos) << px.out;
    const std::string image = px.out.substr(at, px.out.find('\n', at) - at);
    EXPECT_NE(image.find("R32G32B32A32_SFLOAT"), std::string::npos) << image;
    EXPECT_NE(image.find("1920 x 1080"), std::string::npos) << image;
    expectFailure(run("budget --method froxels --lights sun,spot:epipolar"),
                  "froxels takes every light of the frame into one grid");
}

// --lights with each light's shadow and method (issue #25): the set budgeted light by light, auto
// where a light gives no method, and each light's method in the JSON.
TEST(Cli, BudgetOfLightsEachWithItsMethod) {
    const auto j =
        run("budget --profile balanced --size 1920x1080 --json --lights "
            "sun,spot:brute-force,spot:unshadowed:cone-march,point:unshadowed");
    ASSERT_EQ(j.exitCode, 0) << j.out;
    const auto parsed = nlohmann::json::parse(j.out);
    ASSERT_EQ(parsed.size(), 1u);
    EXPECT_EQ(parsed[0]["lightMethods"],
              nlohmann::json({"epipolar", "brute-force", "cone-march", "epipolar"}));
    EXPECT_EQ(parsed[0]["lights"],
              "sun:shadowed:epipolar,spot:shadowed:brute-force,spot:unshadowed:cone-march,"
              "point:unshadowed:epipolar");
    // Only the first light samples epipolarly: its textures are listed, the others' are not.
    std::string names;
    for (const auto& e : parsed[0]["resources"]) names += e["name"].get<std::string>() + "\n";
    EXPECT_NE(names.find("1D min/max trees (light 0)"), std::string::npos) << names;
    EXPECT_EQ(names.find("1D min/max trees (light 1)"), std::string::npos) << names;
    // A light its method refuses, and a word that is neither a shadow nor a method.
    expectFailure(run("budget --lights sun:beam-tree-analytic"),
                  "budget lights[0]: method beam-tree-analytic");
    expectFailure(run("budget --lights spot:dim"),
                  "--lights spot:dim: 'spot:dim': 'dim' is not shadowed, unshadowed or a "
                  "method's or a preset's name");
}

TEST(Cli, BudgetPrintsEveryProfileBesideTheSeed) {
    const auto r = run("budget");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    for (const char* p : {"high-quality", "balanced", "high-performance", "low-balanced"})
        EXPECT_NE(r.out.find(p), std::string::npos) << p;
    EXPECT_NE(r.out.find("seed 000: 88.0 MB at 2560x1600"), std::string::npos) << r.out;
    const auto j = run("budget --profile balanced --size 1920x1080 --shadow-map 1024 --json");
    ASSERT_EQ(j.exitCode, 0) << j.out;
    const auto parsed = nlohmann::json::parse(j.out);
    ASSERT_EQ(parsed.size(), 1u);
    EXPECT_EQ(parsed[0]["shadowMapSize"], 1024);
    EXPECT_LT(parsed[0]["peakBytes"].get<uint64_t>(), parsed[0]["totalBytes"].get<uint64_t>());
}

TEST(Cli, GraphDumpsTheCompiledFrameGraph) {
    const auto dot =
        run("graph " + scene("window_room") + " --dot --size 64x36 --method epipolar --validation");
    ASSERT_EQ(dot.exitCode, 0) << dot.out;
    EXPECT_NE(dot.out.find("digraph"), std::string::npos);
    EXPECT_NE(dot.out.find("ray march with min/max trees"), std::string::npos);
    const auto json = run("graph " + scene("window_room") +
                          " --json --size 64x36 --method brute-force --validation");
    ASSERT_EQ(json.exitCode, 0) << json.out;
    const auto j = nlohmann::json::parse(json.out);
    bool brute = false;
    for (const auto& p : j["passes"]) brute |= p["name"] == "brute-force ray march";
    EXPECT_TRUE(brute);
}

TEST(Cli, FailuresNameWhatIsWrong) {
    expectFailure(run("render missing.json --size 8x8"), "missing.json");
    writeFile("broken.json", "{ \"camera\": { ");
    expectFailure(run("render broken.json --size 8x8"), "broken.json");
    writeFile("badfield.json", R"({"light": {"type": "laser"}})");
    expectFailure(run("render badfield.json --size 8x8"), "light.type");
    expectFailure(run("render " + scene("atrium") + " --method raytrace"),
                  "unknown method 'raytrace'");
    expectFailure(run("render " + scene("atrium") + " --profile ultra"), "unknown profile 'ultra'");
    expectFailure(run("render " + scene("atrium") + " --size 0x5"), "--size '0x5'");
    expectFailure(run("render " + scene("atrium") + " --out picture.jpg"), "picture.jpg");
    expectFailure(run("budget --profile ultra"), "unknown profile 'ultra'");
    expectFailure(run("render " + scene("atrium") + " --frobnicate"), "--frobnicate");
    expectFailure(run("graph " + scene("atrium")), "--dot or --json");
    expectFailure(run("teleport"), "unknown command 'teleport'");
    // Nothing half-written.
    EXPECT_FALSE(exists("picture.jpg"));
    EXPECT_FALSE(exists("missing.png"));
    for (const auto& e : std::filesystem::directory_iterator(cli_test::scratch()))
        EXPECT_EQ(e.path().string().find(".partial"), std::string::npos) << e.path();
}

TEST(Cli, ANonexistentDeviceIsAClearError) {
    expectFailure(run("render " + scene("atrium") + " --size 8x8 --device no-such-gpu"),
                  "no-such-gpu");
}

TEST(Cli, PatternRendersTheRuntimesTestPattern) {
    const auto r =
        run("pattern --size 64x48 --out pattern.png --report pattern.json --dot pattern.dot "
            "--validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_TRUE(exists("pattern.png"));
    EXPECT_TRUE(exists("pattern.dot"));
    std::ifstream report(path("pattern.json"));
    const auto j = nlohmann::json::parse(report);
    EXPECT_LT(j["totals"]["aliasedBytes"].get<uint64_t>(),
              j["totals"]["unaliasedBytes"].get<uint64_t>());
}

TEST(Cli, BenchRunsTheSmallConfigurationAndPlotsIt) {
    const auto r = run("bench --config " + std::string(LS_SOURCE_DIR) +
                       "/bench/small.json --out bench --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::ifstream csv(path("bench/bench.csv"));
    std::string line;
    int rows = -1;
    while (std::getline(csv, line)) ++rows;
    EXPECT_EQ(rows, 16);
    std::ifstream j(path("bench/bench.json"));
    const auto parsed = nlohmann::json::parse(j);
    for (const auto& run : parsed["runs"]) {
        EXPECT_EQ(run["nonFinite"], 0) << run["label"];
        EXPECT_GT(run["time"]["median"].get<double>(), 0.0) << run["label"];
        ASSERT_TRUE(run.contains("error")) << run["label"];
        EXPECT_LT(run["error"]["meanRelative"].get<double>(), 0.2) << run["label"];
    }
    EXPECT_TRUE(exists("bench/strips/window_room_brute-force.png"));
    ASSERT_EQ(
        std::system(("/usr/bin/python3 " + std::string(LS_SOURCE_DIR) + "/scripts/plot_bench.py " +
                     path("bench") + " " + path("plots") + " > /dev/null")
                        .c_str()),
        0);
    EXPECT_TRUE(exists("plots/time_vs_error_window_room.png"));
}
