// The command line's options and messages (issue #8): numbers that used to wrap around, repeated
// options, --help per command, --profile custom and --settings, and errors that said the wrong
// thing or said it twice.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

using cli_test::expectFailure;
using cli_test::path;
using cli_test::run;
using cli_test::scene;
using cli_test::writeFile;

TEST(CliOptions, NumbersNeverWrapAround) {
    const std::string atrium = scene("atrium");
    expectFailure(run("render " + atrium + " --frames 4294967297"),
                  "--frames '4294967297' is not a whole number from 1 to 100000");
    expectFailure(run("render " + atrium + " --size 4294967328x4294967314"),
                  "--size '4294967328x4294967314' is not WIDTHxHEIGHT with both whole numbers from "
                  "1 to 16384");
    expectFailure(run("budget --shadow-map -1"),
                  "--shadow-map '-1' is not a whole number from 1 to 16384");
    expectFailure(run("budget --shadow-map 1024x"), "--shadow-map '1024x'");
    expectFailure(run("render " + atrium + " --frames +3"), "--frames '+3'");
    expectFailure(run("pattern --size 64x48junk"), "--size '64x48junk'");
}

TEST(CliOptions, ARepeatedOptionIsCalledRepeated) {
    expectFailure(run("render " + scene("atrium") + " --size 8x8 --size 9x9"),
                  "option --size is given more than once");
    expectFailure(run("budget --json --json"), "option --json is given more than once");
}

TEST(CliOptions, HelpAfterEachCommandPrintsItsUsage) {
    for (const char* command : {"render", "budget", "graph", "view", "bench", "pattern"}) {
        for (const char* help : {"--help", "-h"}) {
            SCOPED_TRACE(std::string(command) + " " + help);
            const auto r = run(std::string(command) + " " + help);
            EXPECT_EQ(r.exitCode, 0) << r.out;
            EXPECT_EQ(r.out.rfind(std::string("usage: lightscatter ") + command, 0), 0u) << r.out;
        }
    }
    // The --settings block (every field of Settings) only for the commands that take the option,
    // and the list of methods and profiles only for those that name them.
    for (const char* command : {"render", "budget", "graph", "view", "bench", "pattern"}) {
        SCOPED_TRACE(command);
        const std::string out = run(std::string(command) + " --help").out;
        const bool settings = std::string(command) != "bench" && std::string(command) != "pattern";
        EXPECT_EQ(out.find("--settings FILE.json  JSON object") != std::string::npos, settings)
            << out;
        EXPECT_EQ(out.find("methods: auto") != std::string::npos, std::string(command) != "pattern")
            << out;
        EXPECT_NE(out.find("common options: --device NAME"), std::string::npos) << out;
    }
    // Anywhere after the command, and with other options.
    const auto r = run("render " + scene("atrium") + " --size 8x8 --help");
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("--settings FILE.json"), std::string::npos) << r.out;
}

TEST(CliOptions, ProfileCustomSaysHowToSetTheSettings) {
    expectFailure(run("render " + scene("atrium") + " --profile custom"),
                  "--profile custom needs --settings FILE.json");
    expectFailure(run("budget --profile custom"), "--profile custom needs --settings FILE.json");
}

TEST(CliOptions, SettingsFileMakesTheCustomProfile) {
    writeFile("settings.json", R"({"slices": 256, "samplesPerSlice": 128, "minMaxTrees": false})");
    const auto r =
        run("render " + scene("window_room") +
            " --size 48x27 --settings settings.json --out s.png --timings s.json --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::ifstream t(path("s.json"));
    const auto timings = nlohmann::json::parse(t);
    EXPECT_EQ(timings["profile"], "custom");
    bool trees = false;
    for (const auto& p : timings["passes"])
        trees |= p["name"].get<std::string>().find("min/max") != std::string::npos;
    EXPECT_FALSE(trees) << timings.dump();

    // Overlaid on --profile: the budget shows the file's slices with the profile's shadow map.
    const auto b = run("budget --profile low-balanced --settings settings.json --json");
    ASSERT_EQ(b.exitCode, 0) << b.out;
    const auto budget = nlohmann::json::parse(b.out);
    ASSERT_EQ(budget.size(), 1u);
    EXPECT_EQ(budget[0]["profile"], "custom");
    EXPECT_EQ(budget[0]["settings"]["epipolar.slices"], 256);
    EXPECT_EQ(budget[0]["settings"]["epipolar.samplesPerSlice"], 128);
    EXPECT_EQ(budget[0]["shadowMapSize"], 1024);

    writeFile("bad.json", R"({"slices": 3})");
    expectFailure(run("graph " + scene("atrium") + " --json --settings bad.json"),
                  "bad.json: slices = 3: must be a multiple of 4 in [4, 16384]");
    writeFile("typo.json", R"({"slice": 256})");
    expectFailure(run("view " + scene("atrium") + " --settings typo.json"),
                  "typo.json: unknown key 'slice'");
    expectFailure(run("budget --profile all --settings settings.json"),
                  "--settings overlays one profile: give --profile NAME, not all");
}
