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
}

TEST(BenchProfileOrder, BadValuesAreOneLineNamingTheField) {
    const std::string head = R"({"scenes": ["scenes/atrium.json"], "profileOrder": )";
    EXPECT_EQ(refusal(head + "3}"), "profileOrder must be an object {\"sizes\": [...]}");
    EXPECT_EQ(refusal(head + R"({"tolerance": 0.1}})"), "profileOrder.sizes is required");
    EXPECT_EQ(refusal(head + R"({"sizes": []}})"), "profileOrder.sizes is empty");
    EXPECT_EQ(refusal(head + R"({"sizes": ["64x36", "64x36"]}})"),
              "profileOrder.sizes lists \"64x36\" twice");
    EXPECT_EQ(refusal(head + R"({"sizes": ["64x36"], "slack": 1}})"),
              "profileOrder: unknown key 'slack' (known: sizes, tolerance)");
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

}  // namespace
