// A frame built from SCENE.json that the plugin refuses is reported in the scene's terms: the
// file first, SCENE.json's field names, not the plugin API's struct fields.
#include <gtest/gtest.h>

#include "scene_to_plugin.h"

TEST(HostPluginRefusal, SceneFieldsInTheScenesNames) {
    EXPECT_EQ(host::pluginRefusalInSceneTerms(
                  "lightscatter: light.halfAngleDegrees = 0: must be in (0, 89]", "a/s.json"),
              "a/s.json: light.halfAngleDegrees = 0: must be in (0, 89] (refused by the plugin)");
    EXPECT_EQ(host::pluginRefusalInSceneTerms("lightscatter: camera.nearPlane = 0: must be > 0",
                                              "s.json"),
              "s.json: camera.near = 0: must be > 0 (refused by the plugin)");
    EXPECT_EQ(
        host::pluginRefusalInSceneTerms(
            "lightscatter: camera.farPlane = 1: must exceed nearPlane (2) unless infiniteFar",
            "s.json"),
        "s.json: camera.far = 1: must exceed camera.near (2) unless camera.infiniteFar is true "
        "(refused by the plugin)");
    EXPECT_EQ(host::pluginRefusalInSceneTerms(
                  "lightscatter: camera.projection * camera.view is singular", "s.json"),
              "s.json: the camera made from camera.position, camera.target, camera.up, "
              "camera.fovYDegrees, camera.near and camera.far is singular (refused by the plugin)");
    EXPECT_EQ(
        host::pluginRefusalInSceneTerms(
            "lightscatter: camera.view element 12 is inf: matrices must be finite", "s.json"),
        "s.json: the view made from camera.position, camera.target and camera.up element 12 is "
        "inf: matrices must be finite (refused by the plugin)");
    EXPECT_EQ(
        host::pluginRefusalInSceneTerms("lightscatter: medium.g = 1: must be in (-1, 1)", "s.json"),
        "s.json: medium.g = 1: must be in (-1, 1) (refused by the plugin)");
}

TEST(HostPluginRefusal, OtherRefusalsKeepThePluginsWords) {
    EXPECT_EQ(host::pluginRefusalInSceneTerms(
                  "lightscatter: depth.format R8_UNORM is not a depth format", "s.json"),
              "the plugin refused the frame: depth.format R8_UNORM is not a depth format");
}
