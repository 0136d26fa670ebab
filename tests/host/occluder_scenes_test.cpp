// The occluder-scaling scenes (scenes/occluders_N, tools/make_scenes/make_occluder_scenes.py): they
// load, give the beam tree N boxes and the floor, none of whose world bounds touch (seed 004's
// assumption of its boxes), the generator writes the shipped files byte for byte, and the tree of
// the 1000-box field needs more triangles than the plugin's first triangle buffer holds (so the GPU
// test of that scene exercises its growth). No GPU.
#include <gtest/gtest.h>

#include <unistd.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "beam_tree/light_volume_mesh.h"
#include "beam_tree/occluders.h"
#include "host_test_helpers.h"
#include "scene/bounding_boxes.h"

namespace {

namespace fs = std::filesystem;

constexpr int kCounts[] = {1, 10, 100, 1000};

std::string scenePath(int count) {
    return std::string(LS_SOURCE_DIR) + "/scenes/occluders_" + std::to_string(count) + ".json";
}

using host_test::readAll;

void worldBounds(const host::OrientedBox& b, glm::vec3& lo, glm::vec3& hi) {
    glm::vec3 extent(0.0f);
    for (int i = 0; i < 3; ++i) extent += glm::abs(b.axes[i]) * b.halfExtents[i];
    lo = b.center - extent;
    hi = b.center + extent;
}

std::vector<ls::beam::Occluder> treeOccluders(const std::vector<host::BoundingBoxes>& boxes) {
    std::vector<ls::beam::Occluder> out;
    for (const auto& b : boxes) {
        ls::beam::Occluder o;
        o.outer = {glm::dvec3(b.outer.center), glm::dmat3(b.outer.axes),
                   glm::dvec3(b.outer.halfExtents)};
        if (b.inner)
            o.inner = ls::beam::OrientedBox{glm::dvec3(b.inner->center), glm::dmat3(b.inner->axes),
                                            glm::dvec3(b.inner->halfExtents)};
        out.push_back(o);
    }
    return out;
}

}  // namespace

TEST(OccluderScenes, LoadAsNBoxesOnAFloorUnderASpotLight) {
    for (int count : kCounts) {
        const host::SceneDesc scene = host::loadSceneFile(scenePath(count));
        EXPECT_EQ(scene.light.type, lightscatter::LightType::Spot) << count;
        EXPECT_GT(scene.light.shadowMapSize, 0u) << count;
        const host::MeshData mesh = host::loadSceneMeshes(scene);
        EXPECT_TRUE(mesh.warnings.empty()) << count;
        const auto boxes = host::boundingBoxes(mesh);
        ASSERT_EQ(boxes.size(), static_cast<size_t>(count) + 1) << count;
        std::vector<glm::vec3> lo(boxes.size()), hi(boxes.size());
        for (size_t i = 0; i < boxes.size(); ++i) {
            EXPECT_TRUE(boxes[i].inner.has_value()) << count << " box " << i << " is not solid";
            worldBounds(boxes[i].outer, lo[i], hi[i]);
        }
        size_t touching = 0;
        for (size_t i = 0; i < boxes.size(); ++i)
            for (size_t j = i + 1; j < boxes.size(); ++j)
                touching += glm::all(glm::lessThanEqual(lo[i], hi[j])) &&
                            glm::all(glm::lessThanEqual(lo[j], hi[i]));
        EXPECT_EQ(touching, 0u) << count << ": seed 004 assumes occluders that do not touch";
    }
}

TEST(OccluderScenes, TheGeneratorWritesTheShippedFiles) {
    const fs::path dir =
        fs::temp_directory_path() / ("ls_occluder_scenes_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string command = "/usr/bin/python3 " + std::string(LS_SOURCE_DIR) +
                                "/tools/make_scenes/make_occluder_scenes.py " + dir.string() +
                                " > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    for (int count : kCounts)
        for (const char* ext : {".json", ".gltf", ".bin"}) {
            const std::string name = "occluders_" + std::to_string(count) + ext;
            EXPECT_EQ(readAll(dir / name), readAll(fs::path(LS_SOURCE_DIR) / "scenes" / name))
                << name
                << " differs from what tools/make_scenes/make_occluder_scenes.py writes: "
                   "regenerate it";
        }
    fs::remove_all(dir);
}

// The plugin's triangle buffer starts at 3 * 4096 points and grows to what a frame needs
// (plugin_api/src/plugin.cpp); the 1000-box field's lit pyramids alone are more than that.
TEST(OccluderScenes, TheThousandBoxTreeOutgrowsTheFirstTriangleBuffer) {
    const host::SceneDesc scene = host::loadSceneFile(scenePath(1000));
    const auto occluders = treeOccluders(host::boundingBoxes(host::loadSceneMeshes(scene)));
    const auto start = std::chrono::steady_clock::now();
    const auto frustum = ls::beam::spotFrustum(
        glm::dvec3(scene.light.position), glm::dvec3(scene.light.direction),
        glm::radians(static_cast<double>(scene.light.outerConeAngleDegrees)), scene.light.range);
    const ls::beam::LightVolume volume = ls::beam::buildLightVolume(frustum, occluders);
    std::vector<glm::vec4> points;
    ls::beam::appendLitPyramids(volume.tree, points);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "1000 boxes: %zu outer and %zu stopper polygons inserted, %zu tree nodes, %zu visible "
        "polygons, "
        "%zu lit-pyramid points, %.1f ms\n",
        volume.outerPolygons, volume.stopperPolygons, volume.tree.nodeCount(),
        volume.tree.visibleSet().size(), points.size(), ms);
    EXPECT_GT(volume.outerPolygons, 1000u);  // every box's light-facing faces went in
    EXPECT_GT(points.size(), size_t{3} * 4096);
}
