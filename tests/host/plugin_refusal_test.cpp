// A frame built from SCENE.json that the plugin refuses is reported in the scene's terms: the
// file first, SCENE.json's field names, not the plugin API's struct fields.
#include <gtest/gtest.h>

#include "scene_to_plugin.h"

TEST(HostPluginRefusal, SceneFieldsInTheScenesNames) {
    EXPECT_EQ(
        host::pluginRefusalInSceneTerms(
            "lightscatter: light.innerConeAngleDegrees = 0: must be in (0, 89]", "a/s.json"),
        "a/s.json: light.innerConeAngleDegrees = 0: must be in (0, 89] (refused by the plugin)");
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
              "s.json: the plugin refused the frame: depth.format R8_UNORM is not a depth format");
    // The scene path too, for a refusal of the method (issue #22: render and graph named no file).
    EXPECT_EQ(
        host::pluginRefusalInSceneTerms("lightscatter: method cone-march renders one light per "
                                        "frame so far; lights holds 3",
                                        "s.json"),
        "s.json: the plugin refused the frame: method cone-march renders one light per frame so "
        "far; lights holds 3");
}

// A scene's "lights", even of one light, is named lights[i] as the scene names it, with the
// single light's translations (issue #22: a list of one light was reported as light.*).
TEST(HostPluginRefusal, ALightOfTheListIsNamedAsTheSceneNamesIt) {
    EXPECT_EQ(
        host::pluginRefusalInSceneTerms(
            "lightscatter: lights[0]: lights[0].light.shadowViewProjection "
            "is singular (all zero): with lights[0].light.shadowMapSize 2048 "
            "it must be the shadow map's world -> light clip matrix",
            "s.json"),
        "s.json: the shadow map's projection made from lights[0] and the scene's bounds is "
        "singular "
        "(all zero): with lights[0].shadowMapSize 2048 it must be the shadow map's world -> light "
        "clip matrix (refused by the plugin)");
    EXPECT_EQ(
        host::pluginRefusalInSceneTerms(
            "lightscatter: lights[2]: lights[2].light.innerConeAngleDegrees = 0: must be in (0, "
            "89]",
            "s.json"),
        "s.json: lights[2].innerConeAngleDegrees = 0: must be in (0, 89] (refused by the plugin)");
}
