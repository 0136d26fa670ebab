// SCENE.json's "lightsFromGltf": KHR_lights_punctual lights read from the glTF's nodes (position
// and -Z axis through the node hierarchy, candela and lux over 683 lm/W, KHR's defaults and cone
// rules), the keys that go with it, each refusal's one line, and the shipped scene against its
// generator and against the same lights written in SCENE.json. No GPU.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "gltf_lights_scene.h"
#include "host_test_helpers.h"
#include "scene/gltf_json.h"
#include "scene/gltf_lights.h"
#include "scene/scene.h"

namespace {

namespace fs = std::filesystem;
using lightscatter::LightType;
using lightscatter::RangeFalloff;

using host_test::expectVec3;
using host_test::readAll;

// A rig rotated 90 degrees about +Y, scaled 2 and moved to x = 10, holding a point light and a
// spot (the spot's node a matrix: turned -90 degrees about X, so its -Z is down); a sun and a spot
// with KHR's defaults at the top level. Light 4 is placed by no node.
const char* kLightsGltf = R"({
  "asset": {"version": "2.0"},
  "scene": 0,
  "scenes": [{"nodes": [0, 3, 4]}],
  "nodes": [
    {"name": "Rig", "translation": [10, 0, 0], "rotation": [0, 0.70710678118654752, 0, 0.70710678118654752],
     "scale": [2, 2, 2], "children": [1, 2]},
    {"name": "BulbNode", "translation": [1, 2, 3], "extensions": {"KHR_lights_punctual": {"light": 0}}},
    {"name": "SpotNode", "matrix": [1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 5, 0, 1],
     "extensions": {"KHR_lights_punctual": {"light": 1}}},
    {"name": "SunNode", "extensions": {"KHR_lights_punctual": {"light": 2}}},
    {"name": "Plain", "translation": [0, 1, 0], "extensions": {"KHR_lights_punctual": {"light": 3}}}
  ],
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [
    {"name": "Bulb", "type": "point", "intensity": 683, "color": [1, 0.5, 0.25]},
    {"name": "Spot", "type": "spot", "intensity": 1366, "range": 12,
     "spot": {"innerConeAngle": 0.2617993877991494, "outerConeAngle": 0.5235987755982988}},
    {"name": "Sun", "type": "directional", "intensity": 6830, "range": 5},
    {"type": "spot"},
    {"name": "Unplaced", "type": "point"}
  ]}}
})";

class GltfLightsTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("host_gltf_lights_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) const {
        const fs::path file = dir_ / name;
        std::ofstream(file, std::ios::binary) << text;
        return file.string();
    }

    // The message loadSceneFile throws for the scene `text`, without the "file: " in front.
    std::string errorFor(const std::string& text) const {
        const std::string file = write("scene.json", text);
        try {
            host::loadSceneFile(file);
        } catch (const host::SceneError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            if (message.rfind(file + ": ", 0) != 0) return "(file not named) " + message;
            return message.substr(file.size() + 2);
        }
        return "(no error)";
    }

    // The message for a scene that takes its lights from the glTF `gltf`, written as lights.gltf;
    // "GLTF" in it stands for that file's path.
    std::string gltfErrorFor(const std::string& gltf, const std::string& keys = "") {
        const std::string path = write("lights.gltf", gltf);
        std::string message =
            errorFor(R"({"gltf": "lights.gltf", "lightsFromGltf": true)" + keys + "}");
        for (size_t at; (at = message.find(path)) != std::string::npos;)
            message.replace(at, path.size(), "GLTF");
        return message;
    }

    fs::path dir_;
};

TEST_F(GltfLightsTest, NodesPlaceTheLightsInTheScenesUnits) {
    write("lights.gltf", kLightsGltf);
    const host::SceneDesc s = host::loadSceneFile(write("scene.json", R"({
      "gltf": "lights.gltf", "lightsFromGltf": true, "gltfLightScale": 2,
      "gltfLightShadows": {"Bulb": 256, "SpotNode": 512}})"));
    ASSERT_EQ(s.lightCount(), 4u);
    EXPECT_TRUE(s.lightList);  // later messages name them lights[i], in this order

    // The rig's depth first: its bulb and spot, then the sun and the plain spot.
    const host::LightDesc& bulb = s.lightAt(0);
    EXPECT_EQ(bulb.type, LightType::Point);
    // (10, 0, 0) + Ry(90) (2 * (1, 2, 3)): (x, y, z) -> (z, y, -x).
    expectVec3(bulb.position, {16, 4, -2});
    // 683 cd / 683 lm/W * scale 2 * color.
    expectVec3(bulb.intensity, {2, 1, 0.5f}, 1e-6f);
    EXPECT_EQ(bulb.range, host::LightDesc().range);  // no range: unbounded
    EXPECT_EQ(bulb.rangeFalloff, RangeFalloff::Cut);
    EXPECT_EQ(bulb.radius, host::LightDesc().radius);
    EXPECT_EQ(bulb.shadowMapSize, 256u);  // by the light's name

    const host::LightDesc& spot = s.lightAt(1);
    EXPECT_EQ(spot.type, LightType::Spot);
    expectVec3(spot.position, {10, 10, 0});  // the rig's scale doubles the node's 5
    expectVec3(spot.direction, {0, -1, 0}, 1e-6f);
    expectVec3(spot.intensity, {4, 4, 4}, 1e-6f);
    EXPECT_FLOAT_EQ(spot.innerConeAngleDegrees, 15.0f);
    EXPECT_FLOAT_EQ(spot.outerConeAngleDegrees, 30.0f);
    EXPECT_FLOAT_EQ(spot.range, 12.0f);
    EXPECT_EQ(spot.rangeFalloff, RangeFalloff::Window);  // KHR's window is the library's
    EXPECT_EQ(spot.shadowMapSize, 512u);                 // by the node's name

    const host::LightDesc& sun = s.lightAt(2);
    EXPECT_EQ(sun.type, LightType::Directional);
    expectVec3(sun.direction, {0, 0, -1}, 1e-6f);    // an unturned node's -Z
    expectVec3(sun.intensity, {20, 20, 20}, 1e-5f);  // 6830 lx / 683 * 2, white
    EXPECT_EQ(sun.range, host::LightDesc().range);   // KHR: a sun has no range
    EXPECT_EQ(sun.shadowMapSize, 2048u);             // SCENE.json's default

    const host::LightDesc& plain = s.lightAt(3);  // KHR's defaults
    EXPECT_EQ(plain.type, LightType::Spot);
    expectVec3(plain.position, {0, 1, 0});
    expectVec3(plain.intensity, glm::vec3(2.0f / 683.0f), 1e-9f);  // intensity 1, color 1
    EXPECT_FLOAT_EQ(plain.innerConeAngleDegrees, lightscatter::limits::kMinConeAngleDegrees);
    EXPECT_FLOAT_EQ(plain.outerConeAngleDegrees, 45.0f);
    EXPECT_EQ(plain.shadowMapSize, 2048u);
}

TEST_F(GltfLightsTest, TheScaleDefaultsToOneAndAPointLightToNoShadowMap) {
    write("lights.gltf", kLightsGltf);
    const host::SceneDesc s = host::loadSceneFile(
        write("scene.json", R"({"gltf": "lights.gltf", "lightsFromGltf": true})"));
    ASSERT_EQ(s.lightCount(), 4u);
    expectVec3(s.lightAt(0).intensity, {1, 0.5f, 0.25f}, 1e-6f);
    EXPECT_EQ(s.lightAt(0).shadowMapSize, 0u);
    EXPECT_EQ(s.lightAt(1).shadowMapSize, 2048u);
    // lightsFromGltf false: the scene's own light, as without the key.
    const host::SceneDesc own = host::loadSceneFile(
        write("own.json", R"({"gltf": "lights.gltf", "lightsFromGltf": false, "light": {}})"));
    EXPECT_EQ(own.lightCount(), 1u);
    EXPECT_FALSE(own.lightList);
}

// A .glb's JSON chunk is read the same way (no BIN chunk needed).
TEST_F(GltfLightsTest, AGlbsJsonChunkIsRead) {
    std::string gltf = R"({"asset": {"version": "2.0"}, "nodes": [{"rotation": [1, 0, 0, 0],
      "extensions": {"KHR_lights_punctual": {"light": 0}}}], "extensions": {"KHR_lights_punctual":
      {"lights": [{"type": "spot", "spot": {"outerConeAngle": 0.5}}]}}})";
    gltf.append((4 - gltf.size() % 4) % 4, ' ');
    auto u32 = [](uint32_t v) {
        return std::string{char(v & 0xff), char(v >> 8 & 0xff), char(v >> 16 & 0xff),
                           char(v >> 24 & 0xff)};
    };
    write("lights.glb", "glTF" + u32(2) + u32(uint32_t(20 + gltf.size())) +
                            u32(uint32_t(gltf.size())) + "JSON" + gltf);
    const host::SceneDesc s = host::loadSceneFile(
        write("scene.json", R"({"gltf": "lights.glb", "lightsFromGltf": true})"));
    ASSERT_EQ(s.lightCount(), 1u);
    expectVec3(s.light.direction, {0, 0, 1}, 1e-6f);  // turned 180 degrees about X
    EXPECT_NEAR(s.light.outerConeAngleDegrees, 0.5 * 180 / std::numbers::pi, 1e-5);
}

TEST_F(GltfLightsTest, TheKeysRules) {
    write("lights.gltf", kLightsGltf);
    EXPECT_EQ(errorFor(R"({"gltf": "lights.gltf", "lightsFromGltf": true, "lights": [{}]})"),
              "\"lightsFromGltf\" and \"lights\" are both given: a scene's lights come from its "
              "glTF file or from SCENE.json, never both");
    EXPECT_EQ(errorFor(R"({"gltf": "lights.gltf", "lightsFromGltf": true, "light": {}})"),
              "\"lightsFromGltf\" and \"light\" are both given: a scene's lights come from its "
              "glTF file or from SCENE.json, never both");
    EXPECT_EQ(errorFor(R"({"lightsFromGltf": true})"),
              "lightsFromGltf needs \"gltf\", the file whose KHR_lights_punctual lights it reads");
    EXPECT_EQ(errorFor(R"({"gltf": "lights.gltf", "gltfLightScale": 2})"),
              "gltfLightScale is read only with \"lightsFromGltf\": true (the scene's lights "
              "come from SCENE.json)");
    EXPECT_EQ(errorFor(R"({"gltf": "lights.gltf", "gltfLightShadows": {}})"),
              "gltfLightShadows is read only with \"lightsFromGltf\": true (the scene's lights "
              "come from SCENE.json)");
    EXPECT_EQ(errorFor(R"({"gltf": "lights.gltf", "lightsFromGltf": 1})"),
              "lightsFromGltf must be true or false");
    EXPECT_EQ(gltfErrorFor(kLightsGltf, R"(, "gltfLightScale": 0)"),
              "gltfLightScale = 0: must be > 0");
    EXPECT_EQ(gltfErrorFor(kLightsGltf, R"(, "gltfLightShadows": {"Lamp": 512})"),
              "gltfLightShadows.Lamp: no KHR_lights_punctual light or node of lights.gltf is "
              "named 'Lamp' (its lights: light 0 'Bulb' (node 1 'BulbNode'); light 1 'Spot' "
              "(node 2 'SpotNode'); light 2 'Sun' (node 3 'SunNode'); light 3 (node 4 'Plain'))");
    EXPECT_EQ(gltfErrorFor(kLightsGltf, R"(, "gltfLightShadows": {"Spot": 512, "SpotNode": 64})"),
              "gltfLightShadows.SpotNode: light 1 'Spot' (node 2 'SpotNode') is also "
              "gltfLightShadows.Spot: give one size per light");
    EXPECT_EQ(gltfErrorFor(kLightsGltf, R"(, "gltfLightShadows": {"Sun": -1})"),
              "gltfLightShadows.Sun = -1: must be in [0, 16384]");
    EXPECT_EQ(gltfErrorFor(kLightsGltf, R"(, "gltfLightShadows": [])"),
              "gltfLightShadows must be an object of shadow-map sizes by light or node name");
}

// A node's light and its transform, for the refusals below.
std::string oneLight(const std::string& light, const std::string& node = "") {
    return R"({"asset": {"version": "2.0"}, "nodes": [{"name": "Lamp", )" + node +
           R"("extensions": {"KHR_lights_punctual": {"light": 0}}}],
      "extensions": {"KHR_lights_punctual": {"lights": [)" +
           light + "]}}}";
}

TEST_F(GltfLightsTest, EachRefusalNamesTheFileTheLightAndTheRule) {
    EXPECT_EQ(gltfErrorFor(R"({"asset": {"version": "2.0"}, "nodes": [{}]})"),
              "lightsFromGltf: GLTF: has no KHR_lights_punctual lights "
              "(extensions.KHR_lights_punctual.lights, a non-empty array)");
    EXPECT_EQ(gltfErrorFor(R"({"asset": {"version": "2.0"}, "nodes": [{}],
      "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point"}]}}})"),
              "lightsFromGltf: GLTF: no node of its default scene places a KHR_lights_punctual "
              "light (a node's extensions.KHR_lights_punctual.light)");
    EXPECT_EQ(gltfErrorFor(R"({"asset": {"version": "2.0"},
      "nodes": [{}, {"extensions": {"KHR_lights_punctual": {"light": 7}}}],
      "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point"}]}}})"),
              "lightsFromGltf: GLTF: nodes[1].extensions.KHR_lights_punctual.light = 7: the file "
              "has 1 KHR_lights_punctual lights");
    EXPECT_EQ(gltfErrorFor(oneLight(R"({"name": "Wide", "type": "spot",
      "spot": {"outerConeAngle": 1.5707963}})")),
              "lightsFromGltf: GLTF: KHR_lights_punctual light 0 'Wide' (node 0 'Lamp'): "
              "spot.outerConeAngle = 1.5707963 (89.99999846476551 degrees): must be at most 89 "
              "degrees (1.5533430342749532), the library's limit: at 90 a spot's cone is no "
              "longer convex");
    EXPECT_EQ(gltfErrorFor(oneLight(R"({"type": "spot",
      "spot": {"innerConeAngle": 0.5, "outerConeAngle": 0.4}})")),
              "lightsFromGltf: GLTF: KHR_lights_punctual light 0 (node 0 'Lamp'): "
              "spot.innerConeAngle = 0.5: must be in [0, outerConeAngle = 0.4]");
    EXPECT_EQ(gltfErrorFor(oneLight(R"({"type": "spot", "spot": {"outerConeAngle": 0.001}})")),
              "lightsFromGltf: GLTF: KHR_lights_punctual light 0 (node 0 'Lamp'): "
              "spot.outerConeAngle = 0.001 (0.057295779513082325 degrees): must be at least 0.1 "
              "degrees, the library's smallest cone");
    EXPECT_EQ(gltfErrorFor(oneLight(R"({"type": "lamp"})")),
              "lightsFromGltf: GLTF: KHR_lights_punctual light 0 (node 0 'Lamp'): type \"lamp\" "
              "is not one of directional, point, spot");
    EXPECT_EQ(gltfErrorFor(oneLight(R"({"type": "point", "range": 0})")),
              "lightsFromGltf: GLTF: KHR_lights_punctual light 0 (node 0 'Lamp'): range = 0: "
              "must be > 0");
    EXPECT_EQ(gltfErrorFor(oneLight(R"({"type": "point", "intensity": -1})")),
              "lightsFromGltf: GLTF: KHR_lights_punctual light 0 (node 0 'Lamp'): intensity = "
              "-1: must be >= 0");
    EXPECT_EQ(gltfErrorFor(oneLight(R"({"type": "point", "color": [1, -1, 1]})")),
              "lightsFromGltf: GLTF: KHR_lights_punctual light 0 (node 0 'Lamp'): color[1] = "
              "-1: must be >= 0");
    EXPECT_EQ(gltfErrorFor(oneLight(R"({"type": "point", "intensity": 1e15})")),
              "lightsFromGltf: GLTF: KHR_lights_punctual light 0 (node 0 'Lamp'): intensity "
              "1e+15 cd x color[0] x gltfLightScale 1 / 683 lm/W = 1464128843338.2139 W/sr: "
              "must be at most 1e+09 (the plugin's limit)");
    EXPECT_EQ(gltfErrorFor(oneLight(R"({"type": "spot"})", R"("scale": [1, 1, 0], )")),
              "lightsFromGltf: GLTF: KHR_lights_punctual light 0 (node 0 'Lamp'): its node's "
              "world -Z axis has zero length (a scale of 0): it has no direction");
    // A node scaled by 1e200 has a plain direction, whose length alone overflows a double (it
    // was called "a scale of 0"); scales that multiply past a double's range are called that.
    EXPECT_EQ(gltfErrorFor(oneLight(R"({"type": "spot"})", R"("scale": [1e200, 1e200, 1e200], )")),
              "(no error)");
    EXPECT_EQ(gltfErrorFor(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"scale": [1e200, 1e200, 1e200], "children": [1]},
                {"name": "Lamp", "scale": [1e200, 1e200, 1e200],
                 "extensions": {"KHR_lights_punctual": {"light": 0}}}],
      "extensions": {"KHR_lights_punctual": {"lights": [{"type": "spot"}]}}})"),
              "lightsFromGltf: GLTF: KHR_lights_punctual light 0 (node 1 'Lamp'): its node's "
              "world -Z axis is not finite (the scales of its node and its parents multiply past "
              "a double's range): it has no direction");
    EXPECT_EQ(gltfErrorFor(oneLight(R"({"type": "point"})", R"("translation": [2e8, 0, 0], )")),
              "lightsFromGltf: GLTF: KHR_lights_punctual light 0 (node 0 'Lamp'): its node's "
              "world position [2e+08, 0, 0] must be within +-1e+08 m");
    EXPECT_EQ(gltfErrorFor(oneLight(R"({"type": "point"})", R"("rotation": [0, 0, 1], )")),
              "lightsFromGltf: GLTF: nodes[0].rotation must be an array of 4 numbers");
    EXPECT_EQ(gltfErrorFor(R"({"asset": {"version": "2.0"},
      "nodes": [{"children": [1]}, {"children": [0]}],
      "scenes": [{"nodes": [0]}],
      "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point"}]}}})"),
              "lightsFromGltf: GLTF: node 0 is reached twice: the node hierarchy must be a tree");
    EXPECT_EQ(gltfErrorFor("{\"asset\": "),
              "lightsFromGltf: GLTF: malformed JSON at byte 11: [json.exception.parse_error.101] "
              "parse error at line 1, column 11: syntax error while parsing value - unexpected "
              "end of input; expected '[', '{', or a literal");
}

TEST_F(GltfLightsTest, TheGeneratorWritesTheShippedScene) {
    const std::string command = "/usr/bin/python3 " + std::string(LS_SOURCE_DIR) +
                                "/tools/make_scenes/make_gltf_lights_scene.py " + dir_.string() +
                                " > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    for (const char* name : {"atrium_gltf_lights.gltf", "atrium_gltf_lights.json"})
        EXPECT_EQ(readAll(dir_ / name), readAll(fs::path(LS_SOURCE_DIR) / "scenes" / name))
            << name
            << " differs from what tools/make_scenes/make_gltf_lights_scene.py writes: "
               "regenerate it";
}

// The shipped scene's glTF lights are the lights of gltf_lights_scene.h, written in SCENE.json,
// to float rounding: LightsFromGltfGpu renders both.
TEST_F(GltfLightsTest, TheShippedSceneHasTheLightsWrittenInSceneJson) {
    const fs::path scenes = fs::path(LS_SOURCE_DIR) / "scenes";
    const host::SceneDesc gltf = host::loadSceneFile((scenes / "atrium_gltf_lights.json").string());
    const host::SceneDesc fromJson = host::loadSceneFile(
        write("as_json.json",
              gltf_lights_test::atriumLightsAsSceneJson((scenes / "atrium.gltf").string())));
    ASSERT_EQ(gltf.lightCount(), 3u);
    ASSERT_EQ(fromJson.lightCount(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE("light " + std::to_string(i));
        const host::LightDesc& a = gltf.lightAt(i);
        const host::LightDesc& b = fromJson.lightAt(i);
        EXPECT_EQ(a.type, b.type);
        EXPECT_EQ(a.position, b.position);
        expectVec3(a.direction, b.direction, 1e-7f);
        expectVec3(a.intensity, b.intensity, 1e-4f);
        EXPECT_FLOAT_EQ(a.innerConeAngleDegrees, b.innerConeAngleDegrees);
        EXPECT_FLOAT_EQ(a.outerConeAngleDegrees, b.outerConeAngleDegrees);
        EXPECT_EQ(a.range, b.range);
        EXPECT_EQ(a.rangeFalloff, b.rangeFalloff);
        EXPECT_EQ(a.radius, b.radius);
        EXPECT_EQ(a.shadowMapSize, b.shadowMapSize);
    }
    EXPECT_EQ(gltf.camera.position, fromJson.camera.position);
    EXPECT_EQ(gltf.medium.betaM, fromJson.medium.betaM);
    // The same triangles: the glTF's lights add nodes, not geometry.
    const host::MeshData a = host::loadSceneMeshes(gltf), b = host::loadSceneMeshes(fromJson);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    EXPECT_EQ(a.indices, b.indices);
    for (size_t v = 0; v < a.vertices.size(); ++v)
        ASSERT_EQ(a.vertices[v].position, b.vertices[v].position) << v;
}

}  // namespace

namespace {

// The glTF's JSON, read for the lights when SCENE.json is read and for the mesh loader's checks
// after, is parsed once (issue #42: twice); a file changed in between is parsed again, and the
// document is not kept past the mesh's load. Counted, not timed.
TEST_F(GltfLightsTest, TheGltfIsParsedOnceForItsLightsAndItsMesh) {
    const size_t before = host::gltfJsonParses();
    const host::SceneDesc s =
        host::loadSceneFile(std::string(LS_SOURCE_DIR) + "/scenes/atrium_gltf_lights.json");
    const host::MeshData mesh = host::loadSceneMeshes(s);
    EXPECT_FALSE(mesh.primitives.empty());
    EXPECT_EQ(host::gltfJsonParses() - before, 1u);
    // Loaded again, the mesh's checks parse it again: nothing was kept past the first load.
    host::loadSceneMeshes(s);
    EXPECT_EQ(host::gltfJsonParses() - before, 2u);

    // The same glTF, changed after its lights were read and before its mesh is loaded.
    const std::string src = std::string(LS_SOURCE_DIR) + "/scenes/";
    const std::string gltf = readAll(src + "atrium_gltf_lights.gltf");
    write("atrium_gltf_lights.gltf", gltf);
    for (const char* file : {"atrium.bin", "atrium_floor.png"}) write(file, readAll(src + file));
    const host::SceneDesc changed = host::loadSceneFile(
        write("scene.json", R"({"gltf": "atrium_gltf_lights.gltf", "lightsFromGltf": true})"));
    write("atrium_gltf_lights.gltf", gltf + "\n");
    host::loadSceneMeshes(changed);
    EXPECT_EQ(host::gltfJsonParses() - before, 4u);
}

}  // namespace
