// The viewer's settings panel under Xvfb, driven by --panel-script through the panel's own edit
// functions: every field of lightscatter::Settings set in turn, and the report of the frame after
// each edit (--report-log: each light's settings as the plugin ran them) shows it; an edit the
// plugin refuses is shown, undone, and the window runs on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

// stb_image's functions are defined by window_test.cpp; in a unity build that file may come first
// in this one, with STB_IMAGE_IMPLEMENTATION defined, and the header must not be read again.
#ifndef STBI_INCLUDE_STB_IMAGE_H
#include <stb/stb_image.h>
#endif

#include "cli_runner.h"
#include "settings_fields.h"

namespace {

using nlohmann::json;

// A value of every field, none its default, each valid for auto on engine_spot (a shadowed spot):
// the noise sends auto to planes, the simplified model to beam-tree-analytic, no shadow sampling
// to cone-march.
const std::map<std::string, json>& testValues() {
    static const std::map<std::string, json> v = {
        {"epipolar.slices", 256},
        {"epipolar.samplesPerSlice", 128},
        {"epipolar.initialSampleStep", 8},
        {"epipolar.refinementThreshold", 0.05},
        {"epipolar.inscatterRefinementThreshold", 0.1},
        {"epipolar.bilateralThreshold", 0.2},
        {"epipolar.minMaxTrees", false},
        {"shadowFilter", "nearest"},
        {"epipolar.fixup", false},
        {"epipolar.fixupMaxSteps", 64},
        {"shadowDepthBias", 0.001},
        {"epipolar.interpolation", "inscattering"},
        {"shadowMapSize", 1024},
        {"coneMarch.samples", 16},
        {"coneMarch.limited", false},
        {"coneMarch.jitter", true},
        {"shadowSampling", false},
        {"planes.count", 64},
        {"planes.spacing", 0.5},
        {"planes.target", "float32"},
        {"planes.scaling", true},
        {"planes.range", 10.0},
        {"planes.dither", false},
        {"planes.blur", 2},
        {"planes.ambient", 0.5},
        {"noiseAmplitude", 0.5},
        {"noiseScale", 2.0},
        {"noiseVelocity", {0.1, 0.2, 0.3, 0.4}},
        {"lightModel", "simplified"},
        {"simplifiedA0", 0.01},
        {"simplifiedA1", 2.0},
        {"froxels.tile", 4},
        {"froxels.slices", 32},
        {"froxels.farDistance", 50.0},
        {"froxels.temporal", true},
        {"froxels.historyWeight", 0.5},
        {"froxels.pixelHistory", true},
    };
    return v;
}

bool same(const json& a, const json& b) {
    if (a.is_number() && b.is_number())
        return std::fabs(a.get<double>() - b.get<double>()) <=
               1e-6 * std::max(1.0, std::fabs(b.get<double>()));
    if (a.is_array() && b.is_array() && a.size() == b.size()) {
        for (size_t i = 0; i < a.size(); ++i)
            if (!same(a[i], b[i])) return false;
        return true;
    }
    return a == b;
}

json readLog(const std::string& name) {
    std::ifstream in(cli_test::path(name));
    return json::parse(in);
}

// The report log's entries of the frames after a script's steps, by step.
std::map<long, json> reportsByStep(const json& log) {
    std::map<long, json> byStep;
    for (const json& e : log)
        if (e["step"].get<long>() >= 0) byStep[e["step"].get<long>()] = e;
    return byStep;
}

}  // namespace

TEST(Panel, SetsEverySettingAndTheNextReportShowsIt) {
    ASSERT_EQ(std::system("command -v xvfb-run > /dev/null"), 0)
        << "xvfb-run is missing (Debian package xvfb)";
    const auto& fields = host::settingFields();
    // A field added to a method's table needs a value here.
    for (const host::SettingField& f : fields)
        ASSERT_TRUE(testValues().count(f.name)) << f.name << " has no test value";
    ASSERT_EQ(testValues().size(), fields.size());
    // Step k sets field k and puts field k - 1 back to its default, so that each edit is judged
    // alone (the noise and the simplified model cannot run together).
    const lightscatter::Settings defaults;
    json script = json::array();
    for (size_t k = 0; k < fields.size(); ++k) {
        json step = {{"settings", {{fields[k].name, testValues().at(fields[k].name)}}}};
        if (k == 0) {
            step["method"] = "auto";
            step["profile"] = "custom";
        } else {
            step["settings"][fields[k - 1].name] = host::fieldJson(defaults, fields[k - 1]);
        }
        script.push_back(step);
    }
    cli_test::writeFile("script.json", script.dump());
    const auto r = cli_test::run("view " + cli_test::scene("engine_spot") +
                                     " --size 64x36 --frames " + std::to_string(fields.size() + 1) +
                                     " --panel-script script.json --report-log log.json"
                                     " --validation",
                                 cli_test::xvfb());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const json log = readLog("log.json");
    std::map<long, json> byStep = reportsByStep(log);
    for (size_t k = 0; k < fields.size(); ++k) {
        const std::string name = fields[k].name;
        ASSERT_TRUE(byStep.count(long(k))) << "no report of the frame after setting " << name;
        const json& e = byStep[long(k)];
        EXPECT_EQ(e["refused"], "") << name;
        ASSERT_FALSE(e["lights"].empty()) << name;
        const json shown = e["lights"][0]["settings"][name];
        EXPECT_TRUE(same(shown, testValues().at(name)))
            << name << ": the report shows " << shown.dump() << ", the panel set "
            << testValues().at(name).dump() << " (method " << e["method"] << ")";
    }
    // The edits that choose auto's method did.
    for (size_t k = 0; k < fields.size(); ++k) {
        const std::string name = fields[k].name;
        if (name == "noiseAmplitude") {
            EXPECT_EQ(byStep[long(k)]["method"], "planes");
        }
        if (name == "shadowSampling") {
            EXPECT_EQ(byStep[long(k)]["method"], "cone-march");
        }
    }
}

TEST(Panel, ARefusedEditIsShownUndoneAndTheWindowRunsOn) {
    ASSERT_EQ(std::system("command -v xvfb-run > /dev/null"), 0)
        << "xvfb-run is missing (Debian package xvfb)";
    cli_test::writeFile("script.json",
                        R"([{"profile": "custom", "settings": {"epipolar.slices": 256}},
                            {"settings": {"epipolar.slices": 6}}, {}])");
    const auto r = cli_test::run("view " + cli_test::scene("engine_spot") +
                                     " --size 64x36 --frames 3 --panel-script script.json"
                                     " --report-log log.json --validation",
                                 cli_test::xvfb());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const json log = readLog("log.json");
    bool seen = false;
    for (const json& e : log) {
        if (e["step"] != 1) continue;
        seen = true;
        EXPECT_NE(e["refused"].get<std::string>().find("epipolar.slices = 6"), std::string::npos)
            << e["refused"];
        EXPECT_EQ(e["lights"][0]["settings"]["epipolar.slices"], 256);  // the last accepted
    }
    EXPECT_TRUE(seen) << log.dump();
}

// The medium edited live (docs/model.md's height fog and fog volumes): each frame after an edit
// runs with it; a fog volume the running method cannot take is refused, shown and undone; and
// a method that takes it then runs it.
TEST(Panel, EditsTheMediaLiveAndARefusedOneIsUndone) {
    ASSERT_EQ(std::system("command -v xvfb-run > /dev/null"), 0)
        << "xvfb-run is missing (Debian package xvfb)";
    cli_test::writeFile("script.json", R"([
        {"method": "epipolar", "medium": {"heightFog": {"baseHeight": 0.5, "falloff": 0.8}}},
        {"medium": {"density": 0.5, "fogVolumes": [{"center": [0, 0.8, -4],
            "halfExtents": [1, 1, 1], "density": 3, "fade": 0.3}]}},
        {"method": "beam-tree-analytic"},
        {"method": "beam-tree-sampling", "medium": {"heightFog": null}},
        {"medium": {"fogVolumes": [{"center": [0, 0.8, -2], "halfExtents": [1, 2, 1],
            "axes": [[0.8, 0, -0.6], [0, 1, 0], [0.6, 0, 0.8]], "density": 1}]}},
        {}])");
    const auto r = cli_test::run("view " + cli_test::scene("engine_spot") +
                                     " --size 64x36 --frames 6 --panel-script script.json"
                                     " --report-log log.json --validation",
                                 cli_test::xvfb());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const json log = readLog("log.json");
    std::map<long, json> byStep = reportsByStep(log);
    ASSERT_EQ(byStep.size(), 6u) << log.dump();
    EXPECT_EQ(byStep[0]["refused"], "");
    EXPECT_EQ(byStep[0]["medium"]["heightFog"]["falloff"], 0.8f);
    EXPECT_EQ(byStep[0]["method"], "epipolar");
    EXPECT_EQ(byStep[1]["refused"], "");
    EXPECT_EQ(byStep[1]["medium"]["density"], 0.5f);
    EXPECT_EQ(byStep[1]["medium"]["fogVolumes"].size(), 1u);
    EXPECT_EQ(byStep[1]["medium"]["fogVolumes"][0]["fade"], 0.3f);
    // beam-tree-analytic integrates a homogeneous medium only: refused, the method undone.
    EXPECT_NE(byStep[2]["refused"].get<std::string>().find("homogeneous medium only"),
              std::string::npos)
        << byStep[2]["refused"];
    EXPECT_EQ(byStep[2]["method"], "epipolar");
    EXPECT_EQ(byStep[3]["refused"], "");
    EXPECT_EQ(byStep[3]["method"], "beam-tree-sampling");
    EXPECT_TRUE(byStep[3]["medium"]["heightFog"].is_null());
    EXPECT_EQ(byStep[4]["medium"]["fogVolumes"][0]["axes"][0][0], 0.8f);
    EXPECT_EQ(byStep[4]["medium"]["fogVolumes"][0]["center"][2], -2.0f);
    EXPECT_EQ(byStep[5]["refused"], "");
}

TEST(Panel, SaveSettingsWritesAFileTheCommandLineReadsBack) {
    ASSERT_EQ(std::system("command -v xvfb-run > /dev/null"), 0)
        << "xvfb-run is missing (Debian package xvfb)";
    cli_test::writeFile("script.json", R"([{"profile": "custom", "method": "epipolar",
        "settings": {"epipolar.slices": 128, "planeBlur": 3, "shadowFilter": "nearest"},
        "save": "saved.json"}])");
    const auto r = cli_test::run("view " + cli_test::scene("engine_spot") +
                                     " --size 64x36 --frames 1 --panel-script script.json"
                                     " --screenshot panel.png --validation",
                                 cli_test::xvfb());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::ifstream in(cli_test::path("saved.json"));
    const json saved = json::parse(in);
    // Each method's fields nested under its member, Settings' own at the top.
    EXPECT_EQ(saved["epipolar"]["slices"], 128);
    EXPECT_EQ(saved["planes"]["blur"], 3);
    EXPECT_EQ(saved["shadowFilter"], "nearest");
    size_t written = 0;
    for (const auto& [key, value] : saved.items()) written += value.is_object() ? value.size() : 1;
    EXPECT_EQ(written, host::settingFields().size());
    // The budget reads it as a --settings file: the saved slices are what it lays out.
    const auto b = cli_test::run(
        "budget --method epipolar --profile custom --settings saved.json"
        " --size 64x36 --json");
    ASSERT_EQ(b.exitCode, 0) << b.out;
    const json budget = json::parse(b.out.substr(b.out.find('[')));
    EXPECT_EQ(budget[0]["settings"]["epipolar.slices"], 128) << b.out;
}

namespace {

// The share of a window's pixels the panel covers: the same frame's screenshot with the panel and
// without it, compared pixel by pixel.
double panelShare(const std::string& size, const std::string& name) {
    double share = -1.0;
    std::vector<std::vector<unsigned char>> shots;
    for (const char* panel : {"", " --no-panel"}) {
        const std::string file = name + (*panel ? "-without.png" : "-with.png");
        const auto r = cli_test::run("view " + cli_test::scene("window_room") + " --size " + size +
                                         " --frames 4 --profile low-high-performance --method "
                                         "epipolar --screenshot " +
                                         file + panel,
                                     cli_test::xvfb("1280x1024x24"));
        EXPECT_EQ(r.exitCode, 0) << r.out;
        int w = 0, h = 0, n = 0;
        unsigned char* px = stbi_load(cli_test::path(file).c_str(), &w, &h, &n, 4);
        if (!px) return share;
        shots.emplace_back(px, px + static_cast<size_t>(w) * h * 4);
        stbi_image_free(px);
    }
    const auto& a = shots[0];
    const auto& b = shots[1];
    if (a.size() != b.size() || a.empty()) return share;
    size_t differ = 0;
    for (size_t i = 0; i < a.size(); i += 4)
        differ += std::abs(int(a[i]) - int(b[i])) + std::abs(int(a[i + 1]) - int(b[i + 1])) +
                      std::abs(int(a[i + 2]) - int(b[i + 2])) >
                  24;
    return static_cast<double>(differ) / static_cast<double>(a.size() / 4);
}

}  // namespace

// On a small window the panel starts collapsed to its title bar, so the picture stays in view; on
// a larger one it opens, at most half the window's width.
TEST(Panel, CollapsesOnASmallWindowAndOpensOnALargeOne) {
    ASSERT_EQ(std::system("command -v xvfb-run > /dev/null"), 0)
        << "xvfb-run is missing (Debian package xvfb)";
    const double small = panelShare("640x360", "small");
    const double large = panelShare("960x540", "large");
    EXPECT_GE(small, 0.0);
    EXPECT_LT(small, 0.05) << "the panel covers " << small << " of a 640x360 window";
    EXPECT_GT(large, 0.15) << "the panel covers " << large << " of a 960x540 window";
    EXPECT_LE(large, 0.52) << "the panel covers " << large << " of a 960x540 window";
}
