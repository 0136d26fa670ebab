// Image regression: each shipped scene's Lin at 96x54 against the reference stored in
// tests/host/references (made by scripts/update-references.sh on lavapipe).
#include <gtest/gtest.h>

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
