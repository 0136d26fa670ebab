// lightscatter bench (issue #8): every run of a configuration is checked before anything renders,
// and errors are printed on a line of their own, not after the progress bar.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "host_test_helpers.h"

using cli_test::expectFailure;
using cli_test::run;
using cli_test::writeFile;

TEST(CliBench, EveryRunIsCheckedBeforeAnyRenders) {
    // The bad value is the last run of a long configuration: it used to be found only when its run
    // came up, after all the others.
    writeFile("late.json",
              R"({"frames": 1, "warmup": 0, "size": "32x18", "scenes": ["scenes/atrium.json"],
        "profiles": ["balanced", "high-quality"], "sweeps": {"initialSampleStep": [4, 3]}})");
    const auto r = run("bench --config late.json --out late");
    expectFailure(r,
                  "late.json: sweeps.initialSampleStep (run 'initialSampleStep=3'): "
                  "epipolar.initialSampleStep = 3: must be a power of two in [1, 128] (the first "
                  "ray-marching samples' spacing)");
    EXPECT_FALSE(cli_test::exists("late/bench.csv")) << "rendered before checking";

    writeFile("wrap.json", R"({"frames": 4294967297, "scenes": ["scenes/atrium.json"]})");
    expectFailure(run("bench --config wrap.json --out wrap"),
                  "wrap.json: frames = 4294967297: must be a whole number from 1 to 10000");
    writeFile("negative.json",
              R"({"scenes": ["scenes/atrium.json"], "sweeps": {"shadowMapSize": [-1]}})");
    expectFailure(
        run("bench --config negative.json --out negative"),
        "negative.json: sweeps.shadowMapSize[] = -1: must be a whole number from 1 to 16384");
    writeFile("size.json", R"({"scenes": ["scenes/atrium.json"], "sweeps": {"size": ["64x"]}})");
    expectFailure(run("bench --config size.json --out size"),
                  "size.json: sweeps.size[] '64x' is not WIDTHxHEIGHT");
    writeFile("scene.json", R"({"scenes": ["scenes/atrium.json", "scenes/no_such_scene.json"]})");
    expectFailure(run("bench --config scene.json --out scene"),
                  "no_such_scene.json: scene file does not exist");
    EXPECT_FALSE(cli_test::exists("scene/bench.csv"));
}

TEST(CliBench, AnErrorDuringTheRunsStartsOnItsOwnLine) {
    // A cached reference that cannot be read fails the first run, after the progress bar was
    // drawn. (Everything the runs write is checked before the first, so the cache is what is left
    // to fail.)
    writeFile("one.json",
              R"({"frames": 1, "warmup": 0, "size": "16x9", "scenes": ["scenes/window_room.json"],
        "methods": ["brute-force"]})");
    ASSERT_EQ(run("bench --config one.json --out one").exitCode, 0);
    int corrupted = 0;
    for (const auto& e : std::filesystem::directory_iterator(cli_test::path("one/references")))
        if (e.path().extension() == ".exr") {
            std::ofstream(e.path(), std::ios::trunc) << "not an OpenEXR file";
            ++corrupted;
        }
    ASSERT_EQ(corrupted, 1);
    const auto r = run("bench --config one.json --out one --validation");
    EXPECT_NE(r.exitCode, 0) << r.out;
    const size_t line = r.out.find("lightscatter: one/references/");
    ASSERT_NE(line, std::string::npos) << r.out;
    EXPECT_EQ(r.out[line - 1], '\n') << r.out;
    EXPECT_NE(r.out.find("cannot read OpenEXR"), std::string::npos) << r.out;
}

// Everything a run writes is checked before the first run (issue #22): a strip that cannot be
// written used to fail its run, after the runs before it.
TEST(CliBench, AStripThatCannotBeWrittenIsFoundBeforeTheFirstRun) {
    writeFile("strip.json",
              R"({"frames": 1, "warmup": 0, "size": "16x9", "scenes": ["scenes/window_room.json"],
        "methods": ["epipolar", "brute-force"]})");
    std::filesystem::create_directories(cli_test::path("strip/strips/window_room_brute-force.png"));
    const auto r = run("bench --config strip.json --out strip");
    expectFailure(r, "--out strip/strips/window_room_brute-force.png: is a directory");
    EXPECT_FALSE(cli_test::exists("strip/bench.csv"));
}

TEST(CliBench, TimingsOnlyRowsCarryTheBeamTreesCpuTime) {
    writeFile("timings.json", R"({"frames": 1, "warmup": 0, "size": "32x18", "measureError": false,
        "scenes": ["scenes/occluders_10.json"], "methods": ["beam-tree-analytic", "epipolar"]})");
    const auto r = run("bench --config timings.json --out timings --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::ifstream j(cli_test::path("timings/bench.json"));
    const auto parsed = nlohmann::json::parse(j);
    ASSERT_EQ(parsed["runs"].size(), 2u);
    for (const auto& row : parsed["runs"]) {
        EXPECT_FALSE(row.contains("error"))
            << row["label"] << ": no reference without measureError";
        EXPECT_EQ(row["occluders"], 11) << row["label"];  // ten boxes and the floor
        const bool tree = row["method"] == "beam-tree-analytic";
        EXPECT_EQ(row["cpuWork"].size(), tree ? 1u : 0u) << row["label"];
        if (tree) {
            EXPECT_GT(row["cpuTime"]["median"].get<double>(), 0.0);
        }
    }
    std::ifstream csv(cli_test::path("timings/bench.csv"));
    std::string header;
    std::getline(csv, header);
    EXPECT_NE(header.find(",cpuWorkMs,occluders"), std::string::npos) << header;

    writeFile("flag.json", R"({"measureError": "no", "scenes": ["scenes/occluders_1.json"]})");
    expectFailure(run("bench --config flag.json --out flag"),
                  "flag.json: measureError = \"no\": must be true or false");
}

// A shadow-map sweep resizes the maps a scene has and gives none to a light without one:
// point_fog's unshadowed point light would otherwise become a cube-shadowed one, which analytic
// refuses, ending the benchmark in the middle. The sweep starts from sweepProfile's settings.
TEST(CliBench, AShadowMapSweepSkipsALightWithoutAShadowMap) {
    writeFile("sweep.json", R"({"frames": 1, "warmup": 0, "size": "16x9", "measureError": false,
        "scenes": ["scenes/point_fog.json", "scenes/engine_spot.json"], "methods": ["analytic", "epipolar"],
        "sweepProfile": "high-performance", "sweeps": {"shadowMapSize": [256], "slices": [256]}})");
    const auto r = run("bench --config sweep.json --out sweep --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::ifstream j(cli_test::path("sweep/bench.json"));
    const auto parsed = nlohmann::json::parse(j);
    std::map<std::string, std::vector<std::string>> labels;
    for (const auto& row : parsed["runs"]) {
        labels[row["scene"].get<std::string>()].push_back(row["label"].get<std::string>());
        if (row["family"] != "profiles") {
            EXPECT_EQ(row["samples"], 512) << "high-performance's samples";
        }
    }
    // analytic takes unshadowed point and spot lights only, so engine_spot has no analytic rows.
    EXPECT_EQ(labels["point_fog"],
              (std::vector<std::string>{"analytic", "epipolar balanced", "slices=256"}));
    EXPECT_EQ(labels["engine_spot"], (std::vector<std::string>{"epipolar balanced", "slices=256",
                                                               "epipolar shadowMap=256"}));
    writeFile("profile.json", R"({"sweepProfile": "custom", "scenes": ["scenes/atrium.json"]})");
    expectFailure(run("bench --config profile.json --out profile"),
                  "profile.json: sweepProfile: unknown profile 'custom'");
}

// "profileShadowMap" gives each of epipolar's profiles its own map, as seed 000 ran them, and the
// other methods the largest (its brute force ran at the high-quality map); a light without a map
// keeps none. Each row says where its map's size came from.
TEST(CliBench, ProfileShadowMapGivesEachProfileItsMap) {
    writeFile("maps.json", R"({"frames": 1, "warmup": 0, "size": "16x9", "measureError": false,
        "scenes": ["scenes/engine_spot.json", "scenes/point_fog.json"], "methods": ["epipolar", "brute-force"],
        "profiles": ["balanced", "high-performance"], "profileShadowMap": true})");
    const auto r = run("bench --config maps.json --out maps --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::ifstream j(cli_test::path("maps/bench.json"));
    const auto parsed = nlohmann::json::parse(j);
    std::map<std::string, std::pair<int, std::string>> maps;
    for (const auto& row : parsed["runs"])
        maps[row["scene"].get<std::string>() + " " + row["label"].get<std::string>()] = {
            row["shadowMapSize"].get<int>(), row["shadowMapFrom"].get<std::string>()};
    using Map = std::pair<int, std::string>;
    EXPECT_EQ(maps["engine_spot epipolar balanced"], (Map{2048, "profile balanced"}));
    EXPECT_EQ(maps["engine_spot epipolar high-performance"],
              (Map{1024, "profile high-performance"}));
    EXPECT_EQ(maps["engine_spot brute-force"], (Map{2048, "profile balanced"}));
    EXPECT_EQ(maps["point_fog epipolar balanced"], (Map{0, "scene"}));
    EXPECT_EQ(maps["point_fog brute-force"], (Map{0, "scene"}));
    writeFile("maps_flag.json", R"({"profileShadowMap": 1, "scenes": ["scenes/atrium.json"]})");
    expectFailure(run("bench --config maps_flag.json --out maps_flag"),
                  "maps_flag.json: profileShadowMap = 1: must be true or false");
}

// "configurations" are named runs of settings no profile gives, on every scene, checked before
// anything renders; every row times the host's frame beside the plugin's (seed 003's baseline). A
// configuration sets settings fields nested under their method's member, by their dotted names or
// by their former flat names.
TEST(CliBench, ConfigurationsRunNamedSettingsOnEveryScene) {
    writeFile("named.json", R"({"frames": 2, "warmup": 0, "size": "16x9", "measureError": false,
        "scenes": ["scenes/engine_spot.json"], "methods": ["brute-force"],
        "configurations": [
          {"label": "seed low", "epipolar": {"slices": 512, "samplesPerSlice": 256},
           "shadowMapSize": 512},
          {"label": "no sampling 16", "method": "cone-march", "coneSamples": 16,
           "shadowSampling": false}]})");
    const auto r = run("bench --config named.json --out named --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::ifstream j(cli_test::path("named/bench.json"));
    const auto parsed = nlohmann::json::parse(j);
    std::map<std::string, nlohmann::json> rows;
    for (const auto& row : parsed["runs"]) rows[row["label"].get<std::string>()] = row;
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows["seed low"]["family"], "configurations");
    EXPECT_EQ(rows["seed low"]["method"], "epipolar");
    EXPECT_EQ(rows["seed low"]["slices"], 512);
    EXPECT_EQ(rows["seed low"]["samples"], 256);
    EXPECT_EQ(rows["seed low"]["shadowMapSize"], 512);
    EXPECT_EQ(rows["no sampling 16"]["method"], "cone-march");
    EXPECT_EQ(rows["no sampling 16"]["coneSamples"], 16);
    EXPECT_FALSE(rows["no sampling 16"]["shadowSampling"].get<bool>());
    for (const auto& [label, row] : rows) {
        EXPECT_GT(row["engineTime"]["mean"].get<double>(), 0.0) << label;
        EXPECT_GE(row["engineTime"]["sd"].get<double>(), 0.0) << label;
        EXPECT_NEAR(row["frameTime"]["mean"].get<double>(),
                    row["engineTime"]["mean"].get<double>() + row["time"]["mean"].get<double>(),
                    1e-6 * row["frameTime"]["mean"].get<double>() + 1e-9)
            << label;
    }
    // With configurations the methods' list may be empty: they are the runs.
    writeFile("only.json", R"({"frames": 1, "warmup": 0, "size": "16x9", "measureError": false,
        "scenes": ["scenes/engine_spot.json"], "methods": [],
        "configurations": [{"label": "seed low", "epipolar.slices": 512,
                            "epipolar.samplesPerSlice": 256}]})");
    const auto only = run("bench --config only.json --out only --validation");
    ASSERT_EQ(only.exitCode, 0) << only.out;
    std::ifstream oj(cli_test::path("only/bench.json"));
    EXPECT_EQ(nlohmann::json::parse(oj)["runs"].size(), 1u);
    writeFile("named_bad.json", R"({"scenes": ["scenes/atrium.json"],
        "configurations": [{"label": "a", "slices": 3}]})");
    expectFailure(run("bench --config named_bad.json --out named_bad"),
                  "named_bad.json: configurations[0] (run 'a'): ");
    writeFile("named_key.json", R"({"scenes": ["scenes/atrium.json"],
        "configurations": [{"label": "a", "slice": 3}]})");
    expectFailure(run("bench --config named_key.json --out named_key"),
                  "named_key.json: configurations[0]: unknown key 'slice'");
}

// A scene may name methods of its own (those that take its lights); rows carry the light count.
TEST(CliBench, AScenesOwnMethodsAndItsLightCount) {
    writeFile("own.json", R"({"frames": 1, "warmup": 0, "size": "16x9", "methods": ["epipolar"],
        "scenes": ["scenes/window_room.json",
                   {"scene": "scenes/atrium_lights.json", "methods": ["brute-force"]}]})");
    const auto r = run("bench --config own.json --out own --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::ifstream j(cli_test::path("own/bench.json"));
    const auto runs = nlohmann::json::parse(j)["runs"];
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[0]["scene"], "window_room");
    EXPECT_EQ(runs[0]["method"], "epipolar");
    EXPECT_EQ(runs[0]["lights"], 1);
    EXPECT_EQ(runs[1]["scene"], "atrium_lights");
    EXPECT_EQ(runs[1]["method"], "brute-force");
    EXPECT_EQ(runs[1]["lights"], 3);
    for (const auto& row : runs) EXPECT_TRUE(row.contains("error")) << row["label"];

    writeFile("badscene.json",
              R"({"scenes": [{"scene": "scenes/atrium.json", "methods": ["nope"]}]})");
    expectFailure(run("bench --config badscene.json --out badscene"),
                  "badscene.json: scenes[0].methods: unknown method 'nope' (known: ");
    writeFile("nofile.json", R"({"scenes": [{"methods": ["epipolar"]}]})");
    expectFailure(run("bench --config nofile.json --out nofile"),
                  "nofile.json: scenes[0].scene is required");
    writeFile("key.json", R"({"scenes": [{"scene": "scenes/atrium.json", "size": "8x8"}]})");
    expectFailure(run("bench --config key.json --out key"),
                  "key.json: scenes[0]: unknown key 'size' (known: scene, methods)");
    writeFile("number.json", R"({"scenes": [3]})");
    expectFailure(
        run("bench --config number.json --out number"),
        "number.json: scenes[0] must be a scene file's path or an object {\"scene\": path, "
        "\"methods\": [...]}");
}

TEST(CliBench, AMotionRowCarriesItsFlickerAndARerunReusesTheReferences) {
    writeFile("motion.json",
              R"({"warmup": 0, "size": "32x18", "scenes": ["scenes/window_room.json"],
        "methods": ["epipolar", "brute-force"], "profiles": ["balanced"],
        "motion": {"what": ["light", "camera"], "frames": 3}})");
    const auto first = run("bench --config motion.json --out motion --validation");
    ASSERT_EQ(first.exitCode, 0) << first.out;
    auto rows = [] {
        std::ifstream j(cli_test::path("motion/bench.json"));
        return nlohmann::json::parse(j)["runs"];
    };
    const auto runs = rows();
    ASSERT_EQ(runs.size(), 4u);  // two methods, each under both motions
    for (const auto& row : runs) {
        EXPECT_EQ(row["frames"], 3) << row["label"];
        EXPECT_EQ(row["motion"]["frames"], 3);
        EXPECT_EQ(row["flicker"]["framePairs"], 2);
        EXPECT_GT(row["flicker"]["referenceChange"].get<double>(), 0.0) << row["label"];
        EXPECT_GE(row["flicker"]["meanExcess"].get<double>(), 0.0);
        EXPECT_GE(row["flicker"]["meanErrorChange"].get<double>(),
                  row["flicker"]["meanExcess"].get<double>());
        EXPECT_TRUE(row.contains("error"));
    }
    EXPECT_EQ(runs[0]["motion"]["what"], "light");
    EXPECT_EQ(runs[1]["motion"]["what"], "camera");
    EXPECT_TRUE(
        cli_test::exists("motion/strips/window_room_brute-force_motion-camera_flicker.png"));
    // Frame 0 is the scene's own pose under both motions: 1 + 2 + 2 references, each with what it
    // cost beside it.
    namespace fs = std::filesystem;
    std::map<std::string, fs::file_time_type> references;
    size_t images = 0;
    for (const auto& e : fs::directory_iterator(cli_test::path("motion/references"))) {
        references[e.path().filename().string()] = fs::last_write_time(e.path());
        if (e.path().extension() != ".exr") continue;
        ++images;
        std::ifstream cost(fs::path(e.path()).replace_extension(".json"));
        const auto parsed = nlohmann::json::parse(cost);
        EXPECT_EQ(parsed["scene"], "window_room");
        EXPECT_GT(parsed["seconds"].get<double>(), 0.0);
    }
    EXPECT_EQ(images, 5u);
    EXPECT_EQ(references.size(), 10u);

    // The rerun renders no reference (the files are as they were) and, judged against the
    // cached images, reproduces the figures exactly.
    const auto second = run("bench --config motion.json --out motion --validation");
    ASSERT_EQ(second.exitCode, 0) << second.out;
    EXPECT_EQ(second.out.find("(reference"), std::string::npos) << second.out;
    for (const auto& e : fs::directory_iterator(cli_test::path("motion/references")))
        EXPECT_EQ(references.at(e.path().filename().string()), fs::last_write_time(e.path()));
    const auto again = rows();
    for (size_t i = 0; i < runs.size(); ++i)
        EXPECT_EQ(again[i]["flicker"], runs[i]["flicker"]) << runs[i]["label"];

    writeFile("still.json",
              R"({"scenes": ["scenes/window_room.json"], "motion": {"what": "wind"}})");
    expectFailure(run("bench --config still.json --out still"),
                  "still.json: motion.what[] = \"wind\": must be \"light\", \"camera\" or "
                  "\"still\"");
    EXPECT_FALSE(cli_test::exists("still/bench.csv"));
}

namespace {

// RFC 4180's grammar, read back: fields split at commas outside quotes, rows at line ends outside
// quotes, a doubled quote inside a quoted field one quote.
std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
    std::vector<std::vector<std::string>> rows(1, std::vector<std::string>(1));
    bool quoted = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
                rows.back().back() += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                rows.back().back() += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            rows.back().emplace_back();
        } else if (c == '\n') {
            rows.emplace_back(1);
        } else {
            rows.back().back() += c;
        }
    }
    if (rows.back().size() == 1 && rows.back()[0].empty()) rows.pop_back();
    return rows;
}

}  // namespace

// Labels with a comma, a quote, a line break, or 2000 characters keep every row at the header's
// column count and read back as given (issue #42: there was no quoting, and a 1024-byte buffer cut
// rows); a run without a reference has as many columns as one with.
TEST(CliBench, CsvRowsKeepTheirColumnsWhateverTheLabel) {
    const std::string longLabel(2000, 'x');
    writeFile("labels.json", R"({"frames": 1, "warmup": 0, "size": "16x9", "measureError": false,
        "scenes": ["scenes/engine_spot.json"], "methods": [],
        "configurations": [{"label": "a,b"}, {"label": "say \"hi\""}, {"label": "two\nlines"},
                           {"label": ")" +
                                 longLabel + R"("}]})");
    const auto r = run("bench --config labels.json --out labels");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto rows = parseCsv(host_test::readAll(cli_test::path("labels/bench.csv")));
    ASSERT_EQ(rows.size(), 5u);
    for (const auto& row : rows) EXPECT_EQ(row.size(), rows[0].size()) << row[1];
    ASSERT_GT(rows[0].size(), 2u);
    EXPECT_EQ(rows[0][1], "label");
    EXPECT_EQ(rows[1][1], "a,b");
    EXPECT_EQ(rows[2][1], "say \"hi\"");
    EXPECT_EQ(rows[3][1], "two\nlines");
    EXPECT_EQ(rows[4][1], longLabel);
}
