// The light-count scaling scenes (scenes/atrium_spots_N, tools/make_scenes/make_lights_scenes.py):
// the generator writes the shipped files byte for byte, and each is the atrium under N shadowed
// spots with the atrium's own camera and medium, so the benchmark's rows differ in the lights
// alone. No GPU.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "host_test_helpers.h"
#include "scene/scene.h"

namespace {

namespace fs = std::filesystem;

constexpr size_t kCounts[] = {1, 2, 4, 8, 16};

using host_test::readAll;

fs::path shippedScene(const std::string& name) {
    return fs::path(LS_SOURCE_DIR) / "scenes" / (name + ".json");
}

}  // namespace

TEST(LightsScenes, TheGeneratorWritesTheShippedFiles) {
    const fs::path dir =
        fs::temp_directory_path() / ("ls_lights_scenes_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string command = "/usr/bin/python3 " + std::string(LS_SOURCE_DIR) +
                                "/tools/make_scenes/make_lights_scenes.py " + dir.string() +
                                " > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    for (size_t count : kCounts) {
        const std::string name = "atrium_spots_" + std::to_string(count) + ".json";
        EXPECT_EQ(readAll(dir / name), readAll(fs::path(LS_SOURCE_DIR) / "scenes" / name))
            << name
            << " differs from what tools/make_scenes/make_lights_scenes.py writes: regenerate it";
    }
    EXPECT_EQ(readAll(dir / "atrium_sun_small_spots.json"),
              readAll(fs::path(LS_SOURCE_DIR) / "scenes" / "atrium_sun_small_spots.json"))
        << "atrium_sun_small_spots.json differs from what the generator writes: regenerate it";
    fs::remove_all(dir);
}

TEST(LightsScenes, EachIsTheAtriumUnderNShadowedSpots) {
    const host::SceneDesc atrium = host::loadSceneFile(shippedScene("atrium").string());
    for (size_t count : kCounts) {
        const host::SceneDesc s =
            host::loadSceneFile(shippedScene("atrium_spots_" + std::to_string(count)).string());
        SCOPED_TRACE(s.path);
        ASSERT_EQ(s.lightCount(), count);
        for (size_t i = 0; i < count; ++i) {
            EXPECT_EQ(s.lightAt(i).type, lightscatter::LightType::Spot);
            EXPECT_GT(s.lightAt(i).shadowMapSize, 0u);
        }
        ASSERT_EQ(s.models.size(), atrium.models.size());
        EXPECT_EQ(s.models[0].path, atrium.models[0].path);
        EXPECT_EQ(s.camera.position, atrium.camera.position);
        EXPECT_EQ(s.camera.target, atrium.camera.target);
        EXPECT_EQ(s.medium.betaM, atrium.medium.betaM);
    }
}
