// Image regression: each shipped scene's Lin at 96x54 against the reference stored in
// tests/host/references (made by scripts/update-references.sh on lavapipe).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "cli_runner.h"
#include "image_compare.h"
#include "image_io.h"

using cli_test::compareImages;

namespace {

std::string reference(const std::string& name) {
    return std::string(LS_SOURCE_DIR) + "/tests/host/references/" + name + "_lin.exr";
}

}  // namespace

TEST(Regression, ShippedScenesMatchTheirReferences) {
    for (const char* name : {"atrium", "window_room", "engine_spot", "point_fog"}) {
        const auto r = cli_test::run(std::string("render ") + cli_test::scene(name) +
                                     " --method epipolar --size 96x54 --out " + name +
                                     ".png --inscatter " + name + "_lin.exr --validation");
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.out;
        const auto got = host::readExr(
            (std::filesystem::path(cli_test::scratch()) / (std::string(name) + "_lin.exr"))
                .string());
        const auto want = host::readExr(reference(name));
        const auto c = compareImages(got.rgba, want.rgba);
        EXPECT_TRUE(c.pass()) << name << ": " << c.describe();
    }
}

TEST(Regression, TheCheckCatchesABrokenPass) {
    const auto want = host::readExr(reference("window_room"));
    EXPECT_TRUE(compareImages(want.rgba, want.rgba).pass());
    // A 6x6 block gone dark, as a fix-up pass that no longer ran would leave it.
    auto broken = want.rgba;
    double peak = 0;
    size_t brightest = 0;
    for (size_t p = 0; p < broken.size() / 4; ++p)
        if (broken[p * 4] > peak) {
            peak = broken[p * 4];
            brightest = p;
        }
    const int cx = static_cast<int>(brightest % want.width),
              cy = static_cast<int>(brightest / want.width);
    for (int y = cy - 3; y < cy + 3; ++y)
        for (int x = cx - 3; x < cx + 3; ++x)
            if (x >= 0 && y >= 0 && x < static_cast<int>(want.width) &&
                y < static_cast<int>(want.height))
                for (int k = 0; k < 3; ++k)
                    broken[(static_cast<size_t>(y) * want.width + static_cast<size_t>(x)) * 4 +
                           static_cast<size_t>(k)] = 0.0f;
    EXPECT_FALSE(compareImages(broken, want.rgba).pass());
    // A light 10% too weak.
    auto dim = want.rgba;
    for (float& v : dim) v *= 0.9f;
    EXPECT_FALSE(compareImages(dim, want.rgba).pass());
}

// A spot's cookie end to end (issue #25): the host decodes scenes/stained_glass_cookie.png, uploads
// it and hands it to the plugin as the light's color, with the shadow map and without, under
// validation. The shafts then take the glass's colors: the ratio of red to blue varies across the
// image, where window_room's uncoloured spot keeps its own ratio everywhere; and the light through
// the glass is dimmer than window_room's (no pane passes more than clear glass).
TEST(Regression, ACookieColoursTheShafts) {
    auto lin = [](const std::string& name, const std::string& method) {
        const auto r = cli_test::run("render " + cli_test::scene(name) + " --method " + method +
                                     " --size 96x54 --out " + name + ".png --inscatter " + name +
                                     "_cookie_lin.exr --validation");
        EXPECT_EQ(r.exitCode, 0) << name << ": " << r.out;
        return host::readExr(
                   (std::filesystem::path(cli_test::scratch()) / (name + "_cookie_lin.exr"))
                       .string())
            .rgba;
    };
    // The spread of red / blue over the pixels that carry light, and the total light.
    auto measure = [](const std::vector<float>& rgba, double& spread, double& total) {
        double lo = 1e30, hi = 0, peak = 0;
        total = 0;
        for (size_t i = 0; i < rgba.size(); i += 4) peak = std::max(peak, double(rgba[i + 1]));
        for (size_t i = 0; i < rgba.size(); i += 4) {
            total += rgba[i] + rgba[i + 1] + rgba[i + 2];
            if (rgba[i + 1] < 0.05 * peak || rgba[i + 2] <= 0.0f) continue;
            const double ratio = rgba[i] / rgba[i + 2];
            lo = std::min(lo, ratio);
            hi = std::max(hi, ratio);
        }
        spread = hi / lo;
    };
    double plainSpread = 0, plainTotal = 0;
    measure(lin("window_room", "epipolar"), plainSpread, plainTotal);
    for (const char* name : {"stained_glass", "stained_glass_unshadowed"}) {
        for (const char* method : {"epipolar", "cone-march"}) {
            SCOPED_TRACE(std::string(name) + ", " + method);
            double spread = 0, total = 0;
            measure(lin(name, method), spread, total);
            std::printf("%s, %s: red/blue spread %.2f (window_room %.2f), light %.3g (%.3g)\n",
                        name, method, spread, plainSpread, total, plainTotal);
            EXPECT_GT(spread, 2.0 * plainSpread);
            if (std::string(name) == "stained_glass") {
                EXPECT_LT(total, plainTotal);
            }
        }
    }
}
