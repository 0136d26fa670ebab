// The benchmark's "profileOrder": epipolar's profile runs repeated at each size, and the check
// that each profile of a chain costs no more than the one before it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "bench/bench_config.h"
#include "bench/profile_order.h"

namespace {

// A configuration file in a folder of its own (ctest runs tests side by side); loads it.
host::bench::BenchConfig load(const std::string& text) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("ls_bench_profile_order_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto file = dir / "order.json";
    std::ofstream(file) << text;
    return host::bench::loadBenchConfig(file.string(), LS_SOURCE_DIR);
}

std::string refusal(const std::string& text) {
    try {
        (void)load(text);
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        return what.substr(what.find(".json: ") + 7);
    }
    return "(accepted)";
}

TEST(BenchProfileOrder, EpipolarsProfilesRunOncePerSize) {
    const host::bench::BenchConfig c = load(R"({"size": "64x36", "scenes": ["scenes/atrium.json"],
                 "methods": ["epipolar", "brute-force"],
                 "profiles": ["balanced", "high-performance"],
                 "profileOrder": {"sizes": ["64x36", "128x72"], "tolerance": 0.1}})");
    ASSERT_TRUE(c.profileOrder);
    EXPECT_EQ(c.profileOrder->tolerance, 0.1);
    ASSERT_EQ(c.runs.size(), 5u);  // two profiles at two sizes, and brute force once
    EXPECT_EQ(c.runs[0].label, "epipolar balanced 64x36");
    EXPECT_TRUE(c.runs[0].measureError);  // at the configuration's size
    EXPECT_EQ(c.runs[1].label, "epipolar balanced 128x72");
    EXPECT_EQ(c.runs[1].size.width, 128u);
    EXPECT_FALSE(c.runs[1].measureError);
    EXPECT_EQ(c.runs[3].label, "epipolar high-performance 128x72");
    EXPECT_EQ(c.runs[4].label, "brute-force");
    EXPECT_FALSE(load(R"({"scenes": ["scenes/atrium.json"]})").profileOrder);
    EXPECT_EQ(c.profileOrder->rounds, 1);
}

// Each scene's profile runs again in every round, all of them in turn before the next round (so
// the device's drift over a round falls on each profile alike); errors in the first round only.
TEST(BenchProfileOrder, RoundsRepeatEachScenesProfilesInTurn) {
    const host::bench::BenchConfig c =
        load(R"({"size": "64x36", "scenes": ["scenes/atrium.json", "scenes/window_room.json"],
                 "methods": ["epipolar", "brute-force"],
                 "profiles": ["balanced", "high-performance"],
                 "profileOrder": {"sizes": ["64x36", "128x72"], "rounds": 3}})");
    ASSERT_TRUE(c.profileOrder);
    EXPECT_EQ(c.profileOrder->rounds, 3);
    ASSERT_EQ(c.runs.size(), 26u);  // per scene: 2 profiles x 2 sizes x 3 rounds, brute force once
    const char* const labels[13] = {"epipolar balanced 64x36",
                                    "epipolar balanced 128x72",
                                    "epipolar high-performance 64x36",
                                    "epipolar high-performance 128x72",
                                    "brute-force",
                                    "epipolar balanced 64x36 round 2",
                                    "epipolar balanced 128x72 round 2",
                                    "epipolar high-performance 64x36 round 2",
                                    "epipolar high-performance 128x72 round 2",
                                    "epipolar balanced 64x36 round 3",
                                    "epipolar balanced 128x72 round 3",
                                    "epipolar high-performance 64x36 round 3",
                                    "epipolar high-performance 128x72 round 3"};
    for (size_t i = 0; i < c.runs.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(c.runs[i].label, labels[i % 13]);
        EXPECT_NE(c.runs[i].scene.find(i < 13 ? "atrium" : "window_room"), std::string::npos);
    }
    EXPECT_EQ(c.runs[5].round, 1);
    EXPECT_EQ(c.runs[12].round, 2);
    EXPECT_EQ(c.runs[5].size.width, 64u);
    EXPECT_TRUE(c.runs[0].measureError);
    EXPECT_FALSE(c.runs[5].measureError);  // the same run's second round
}

TEST(BenchProfileOrder, BadValuesAreOneLineNamingTheField) {
    const std::string head = R"({"scenes": ["scenes/atrium.json"], "profileOrder": )";
    EXPECT_EQ(refusal(head + "3}"), "profileOrder must be an object {\"sizes\": [...]}");
    EXPECT_EQ(refusal(head + R"({"tolerance": 0.1}})"), "profileOrder.sizes is required");
    EXPECT_EQ(refusal(head + R"({"sizes": []}})"), "profileOrder.sizes is empty");
    EXPECT_EQ(refusal(head + R"({"sizes": ["64x36", "64x36"]}})"),
              "profileOrder.sizes lists \"64x36\" twice");
    EXPECT_EQ(refusal(head + R"({"sizes": ["64x36"], "slack": 1}})"),
              "profileOrder: unknown key 'slack' (known: sizes, tolerance, rounds)");
    EXPECT_EQ(refusal(head + R"({"sizes": ["64x36"], "rounds": 0}})"),
              "profileOrder.rounds = 0: must be a whole number from 1 to 100");
    EXPECT_EQ(refusal(head + R"({"sizes": ["64x36"], "rounds": 2.5}})"),
              "profileOrder.rounds = 2.5: must be a whole number from 1 to 100");
    EXPECT_EQ(refusal(head + R"({"sizes": ["64x36"], "tolerance": -1}})"),
              "profileOrder.tolerance = -1: must be a number from 0 to 10");
}

nlohmann::json row(const std::string& scene, const std::string& profile, unsigned width,
                   double ms) {
    return {{"scene", scene},     {"family", "profiles"},       {"method", "epipolar"},
            {"profile", profile}, {"size", {width, width / 2}}, {"time", {{"median", ms}}}};
}

TEST(BenchProfileOrder, EachChainIsCheckedPerSceneAndSize) {
    nlohmann::json runs = nlohmann::json::array();
    // In order, and within 5% (104 after 100).
    runs.push_back(row("a", "high-quality", 64, 200));
    runs.push_back(row("a", "balanced", 64, 100));
    runs.push_back(row("a", "high-performance", 64, 104));
    // Out of order by 6%, at another size: only that size is named.
    runs.push_back(row("a", "high-quality", 128, 200));
    runs.push_back(row("a", "balanced", 128, 212));
    // The low chain of another scene: its last profile the slowest; the high chain's missing
    // profiles are not compared.
    runs.push_back(row("b", "low-high-quality", 64, 100));
    runs.push_back(row("b", "low-balanced", 64, 80));
    runs.push_back(row("b", "low-high-performance", 64, 90));
    runs.push_back(row("b", "balanced", 64, 1000));
    // Other methods and families are not profiles.
    nlohmann::json brute = row("b", "balanced", 64, 1);
    brute["method"] = "brute-force";
    runs.push_back(brute);
    nlohmann::json sweep = row("b", "high-performance", 64, 5000);
    sweep["family"] = "epipolar.slices";
    runs.push_back(sweep);

    const host::bench::ProfileOrderCheck check = host::bench::checkProfileOrder(runs, 0.05);
    EXPECT_EQ(check.pairs, 5u);
    ASSERT_EQ(check.broken.size(), 2u);
    EXPECT_EQ(check.broken[0],
              "a 128x64: balanced takes 212.0 ms, 6.0% more than high-quality's 200.0 ms");
    EXPECT_EQ(check.broken[1],
              "b 64x32: low-high-performance takes 90.0 ms, 12.5% more than low-balanced's "
              "80.0 ms");
    EXPECT_TRUE(host::bench::checkProfileOrder(runs, 0.2).broken.empty());
}

// Rows repeated by rounds count once per pair, each profile at the median of its rounds: one slow
// round of three does not put a profile out of order, two do.
TEST(BenchProfileOrder, RoundsCountAtTheirMedian) {
    nlohmann::json runs = nlohmann::json::array();
    for (double ms : {100.0, 96.0, 104.0}) runs.push_back(row("a", "balanced", 64, ms));
    for (double ms : {90.0, 150.0, 95.0}) runs.push_back(row("a", "high-performance", 64, ms));
    host::bench::ProfileOrderCheck check = host::bench::checkProfileOrder(runs, 0.05);
    EXPECT_EQ(check.pairs, 1u);
    EXPECT_TRUE(check.broken.empty());
    runs.push_back(row("a", "high-performance", 64, 140.0));
    runs.push_back(row("a", "high-performance", 64, 130.0));  // 90, 95, 130, 140, 150: 130
    check = host::bench::checkProfileOrder(runs, 0.05);
    ASSERT_EQ(check.broken.size(), 1u);
    EXPECT_EQ(check.broken[0],
              "a 64x32: high-performance takes 130.0 ms, 30.0% more than balanced's 100.0 ms");
}

}  // namespace
