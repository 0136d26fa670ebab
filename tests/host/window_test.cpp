// The window under Xvfb: open, render some frames, resize, screenshot; the screenshot must show the
// scene (not a blank or uniform image), at the size the window was resized to.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

TEST(Window, OpensRendersResizesAndShowsTheScene) {
    ASSERT_EQ(std::system("command -v xvfb-run > /dev/null"), 0)
        << "xvfb-run is missing (Debian package xvfb)";
    const auto r = cli_test::run("view " + cli_test::scene("atrium") +
                                     " --size 160x90 --frames 8 --resize-at 3 --resize-to 200x120"
                                     " --screenshot window.png --no-panel --validation",
                                 cli_test::xvfb());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const std::string shot = (std::filesystem::path(cli_test::scratch()) / "window.png").string();
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load(shot.c_str(), &w, &h, &n, 4);
    ASSERT_NE(px, nullptr);
    EXPECT_EQ(w, 200);
    EXPECT_EQ(h, 120);
    // A scene has structure: many distinct levels and a spread of brightness.
    double sum = 0, sum2 = 0;
    int distinct[256] = {};
    for (int i = 0; i < w * h; ++i) {
        const double y = 0.2126 * px[i * 4] + 0.7152 * px[i * 4 + 1] + 0.0722 * px[i * 4 + 2];
        sum += y;
        sum2 += y * y;
        distinct[static_cast<int>(y)] = 1;
    }
    stbi_image_free(px);
    const double mean = sum / (w * h), stddev = std::sqrt(sum2 / (w * h) - mean * mean);
    int levels = 0;
    for (int d : distinct) levels += d;
    EXPECT_GT(mean, 5.0);
    EXPECT_LT(mean, 250.0);
    EXPECT_GT(stddev, 5.0);
    EXPECT_GT(levels, 40);
}

// The window's tone mapping (host_example/shaders/tonemap.frag) at an exposure that puts every lit
// pixel far beyond 1e19: the ACES fit used to overflow there to NaN, which the swapchain stores as
// black.
TEST(Window, VeryBrightPixelsStayWhite) {
    ASSERT_EQ(std::system("command -v xvfb-run > /dev/null"), 0)
        << "xvfb-run is missing (Debian package xvfb)";
    std::ifstream in(cli_test::scene("atrium"));
    nlohmann::json scene = nlohmann::json::parse(in);
    scene["gltf"] = std::string(LS_SOURCE_DIR) + "/scenes/" + scene["gltf"].get<std::string>();
    scene["exposure"] = 1e30;
    const auto dir = std::filesystem::path(cli_test::scratch());
    std::ofstream(dir / "bright.json") << scene.dump();
    const auto r = cli_test::run(
        "view bright.json --size 64x36 --frames 2 --screenshot bright.png"
        " --no-panel --validation",
        cli_test::xvfb());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load((dir / "bright.png").string().c_str(), &w, &h, &n, 4);
    ASSERT_NE(px, nullptr);
    int white = 0;
    for (int i = 0; i < w * h; ++i)
        white += px[i * 4] == 255 && px[i * 4 + 1] == 255 && px[i * 4 + 2] == 255;
    stbi_image_free(px);
    EXPECT_EQ(white, w * h);
}

// Seed 002's planes in the window, with the scrolling noise on: each frame carries the time
// since the window opened (FrameDescription::timeSeconds).
TEST(Window, PlanesWithScrollingNoise) {
    ASSERT_EQ(std::system("command -v xvfb-run > /dev/null"), 0)
        << "xvfb-run is missing (Debian package xvfb)";
    const auto dir = std::filesystem::path(cli_test::scratch());
    std::ofstream(dir / "noise.json") << R"({"noiseAmplitude": 0.5, "planeCount": 24})";
    const auto r = cli_test::run("view " + cli_test::scene("window_room") +
                                     " --method planes --settings noise.json --size 64x36"
                                     " --frames 3 --screenshot noise.png --validation",
                                 cli_test::xvfb());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load((dir / "noise.png").string().c_str(), &w, &h, &n, 4);
    ASSERT_NE(px, nullptr);
    stbi_image_free(px);
    EXPECT_EQ(w, 64);
    EXPECT_EQ(h, 36);
}
