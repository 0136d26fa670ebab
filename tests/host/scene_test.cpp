// loadSceneFile: every field, the defaults, path resolution, and each rule's one-line error.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>

#include "host_test_helpers.h"
#include "scene/scene.h"

namespace {

namespace fs = std::filesystem;

const std::string kBox = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf";

using host_test::expectVec3;
// What the reader parses lands within a float's rounding of the file's decimal.
constexpr float kParsed = 1e-6f;

glm::vec3 apply(const glm::mat4& m, const glm::vec3& p) {
    return glm::vec3(m * glm::vec4(p, 1));
}

class SceneFileTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("host_scene_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) const {
        const fs::path file = dir_ / name;
        fs::create_directories(file.parent_path());
        std::ofstream(file) << text;
        return file.string();
    }

    // The message loadSceneFile throws for `text`, without the "file: " in front.
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

    fs::path dir_;
};

TEST_F(SceneFileTest, AFullFileSetsEveryField) {
    write("model.glb", "");
    const std::string file = write("full.json", R"({
      "gltf": "model.glb",
      "models": [{"gltf": ")" + kBox + R"(", "translation": [1, 2, 3]}],
      "camera": {"position": [1, 2, 3], "target": [4, 2, 3], "up": [0, 0, 2],
                 "fovYDegrees": 45, "near": 0.5, "far": 250, "reversedZ": true, "infiniteFar": true},
      "light": {"type": "spot", "position": [0, 10, 0], "direction": [0, -3, 4],
                "intensity": [100, 90, 80], "halfAngleDegrees": 89, "range": 40, "radius": 0.2,
                "shadowMapSize": 0},
      "medium": {"betaR": [1e-5, 2e-5, 3e-5], "betaM": [0.01, 0.02, 0.03], "g": -0.5,
                 "sigmaA": [0, 0.001, 0], "phase": "isotropic", "maxDistance": 500},
      "sky": {"color": [0.1, 0.2, 0.3]},
      "ambient": [0.01, 0.02, 0.03],
      "exposure": 0.8
    })");
    const host::SceneDesc s = host::loadSceneFile(file);
    EXPECT_EQ(s.path, file);
    ASSERT_EQ(s.models.size(), 2u);
    EXPECT_EQ(s.models[0].path, (dir_ / "model.glb").string());
    EXPECT_EQ(s.models[0].transform, glm::mat4(1.0f));
    EXPECT_EQ(s.models[1].path, kBox);
    expectVec3(apply(s.models[1].transform, {0, 0, 0}), {1, 2, 3}, kParsed);

    expectVec3(s.camera.position, {1, 2, 3}, kParsed);
    expectVec3(s.camera.target, {4, 2, 3}, kParsed);
    expectVec3(s.camera.up, {0, 0, 1}, kParsed);  // normalized
    EXPECT_FLOAT_EQ(s.camera.fovYDegrees, 45.0f);
    EXPECT_FLOAT_EQ(s.camera.nearPlane, 0.5f);
    EXPECT_FLOAT_EQ(s.camera.farPlane, 250.0f);
    EXPECT_TRUE(s.camera.reversedZ);
    EXPECT_TRUE(s.camera.infiniteFar);

    EXPECT_EQ(s.light.type, lightscatter::LightType::Spot);
    expectVec3(s.light.position, {0, 10, 0}, kParsed);
    expectVec3(s.light.direction, {0, -0.6f, 0.8f}, kParsed);  // (0, -3, 4) / 5
    expectVec3(s.light.intensity, {100, 90, 80}, kParsed);
    EXPECT_FLOAT_EQ(s.light.innerConeAngleDegrees, 89.0f);
    EXPECT_FLOAT_EQ(s.light.outerConeAngleDegrees, 89.0f);
    EXPECT_FLOAT_EQ(s.light.range, 40.0f);
    EXPECT_FLOAT_EQ(s.light.radius, 0.2f);
    EXPECT_EQ(s.light.shadowMapSize, 0u);

    expectVec3(s.medium.betaR, {1e-5f, 2e-5f, 3e-5f}, 1e-12f);
    expectVec3(s.medium.betaM, {0.01f, 0.02f, 0.03f}, kParsed);
    EXPECT_FLOAT_EQ(s.medium.g, -0.5f);
    expectVec3(s.medium.sigmaA, {0, 0.001f, 0}, kParsed);
    EXPECT_EQ(s.medium.phase, lightscatter::MiePhase::Isotropic);
    EXPECT_FLOAT_EQ(s.medium.maxDistance, 500.0f);
    expectVec3(s.skyColor, {0.1f, 0.2f, 0.3f}, kParsed);
    expectVec3(s.ambient, {0.01f, 0.02f, 0.03f}, kParsed);
    EXPECT_FLOAT_EQ(s.exposure, 0.8f);
}

// docs/model.md's non-uniform medium in SCENE.json: every field read, absent ones leaving the
// homogeneous medium, and each broken rule one line naming the field.
TEST_F(SceneFileTest, TheMediaFieldsAreReadAndEachBrokenRuleNamed) {
    const std::string file = write("scene.json", R"({"medium": {"density": 0.25,
        "heightFog": {"baseHeight": 3, "falloff": 0.5},
        "fogVolumes": [{"center": [1, 2, 3], "halfExtents": [4, 5, 6], "density": 2, "fade": 0.5,
                        "axes": [[0.6, 0, 0.8], [0, 1, 0], [-0.8, 0, 0.6]]},
                       {"center": [0, 0, 0], "halfExtents": [1, 1, 1]}]}})");
    const host::SceneDesc s = host::loadSceneFile(file);
    EXPECT_EQ(s.medium.density, 0.25f);
    ASSERT_TRUE(s.medium.heightFog);
    EXPECT_EQ(s.medium.heightFog->baseHeight, 3.0f);
    EXPECT_EQ(s.medium.heightFog->falloff, 0.5f);
    ASSERT_EQ(s.medium.fogVolumes.size(), 2u);
    EXPECT_EQ(s.medium.fogVolumes[0].center[2], 3.0f);
    EXPECT_EQ(s.medium.fogVolumes[0].halfExtents[1], 5.0f);
    EXPECT_EQ(s.medium.fogVolumes[0].axes[2][0], -0.8f);
    EXPECT_EQ(s.medium.fogVolumes[0].fade, 0.5f);
    EXPECT_EQ(s.medium.fogVolumes[1].density, 1.0f);  // the defaults
    EXPECT_EQ(s.medium.fogVolumes[1].axes[0][0], 1.0f);
    EXPECT_TRUE(s.medium.nonUniform());
    EXPECT_FALSE(host::loadSceneFile(write("plain.json", "{}")).medium.nonUniform());

    EXPECT_EQ(errorFor(R"({"medium": {"density": -1}})"),
              "medium.density = -1: must be in [0, 1000]");
    EXPECT_EQ(errorFor(R"({"medium": {"heightFog": {"falloff": 1e5}}})"),
              "medium.heightFog.falloff = 1e+05: must be in [0, 10000]");
    EXPECT_EQ(errorFor(R"({"medium": {"heightFog": {"height": 1}}})"),
              "medium.heightFog: unknown key 'height' (known keys: baseHeight, falloff)");
    EXPECT_EQ(errorFor(R"({"medium": {"fogVolumes": {}}})"),
              "medium.fogVolumes must be an array of fog volume objects");
    EXPECT_EQ(errorFor(R"({"medium": {"fogVolumes": [{"center": [0, 0, 0]}]}})"),
              "medium.fogVolumes[0] needs \"center\" and \"halfExtents\"");
    EXPECT_EQ(errorFor(R"({"medium": {"fogVolumes": [{"center": [0, 0, 0], "halfExtents": [1, 1, 1],
        "axes": [[2, 0, 0], [0, 1, 0], [0, 0, 1]]}]}})"),
              "medium.fogVolumes[0].axes[0] has length 2: the axes must be unit vectors (within "
              "1e-3)");
    EXPECT_EQ(errorFor(R"({"medium": {"fogVolumes": [{"center": [0, 0, 0], "halfExtents": [1, 1, 1],
        "axes": [[1, 0, 0], [0.6, 0.8, 0], [0, 0, 1]]}]}})"),
              "medium.fogVolumes[0].axes[1] and medium.fogVolumes[0].axes[0] have dot product "
              "0.6: the axes must be orthogonal (within 1e-3)");
    EXPECT_EQ(
        errorFor(
            R"({"medium": {"fogVolumes": [{"center": [0, 0, 0], "halfExtents": [1, -1, 1]}]}})"),
        "medium.fogVolumes[0].halfExtents[1] = -1: must be in [0, 1e+08]");
    std::string many = R"({"medium": {"fogVolumes": [)";
    for (int i = 0; i < 65; ++i)
        many += std::string(i ? "," : "") + R"({"center": [0, 0, 0], "halfExtents": [1, 1, 1]})";
    EXPECT_EQ(errorFor(many + "]}}"), "medium.fogVolumes holds 65 volumes: at most 64");
}

TEST_F(SceneFileTest, MissingFieldsKeepTheDefaults) {
    const std::string file = write("empty.json", R"({"camera": {}, "light": {}, "medium": {}})");
    const host::SceneDesc s = host::loadSceneFile(file);
    const host::SceneDesc d;
    EXPECT_TRUE(s.models.empty());
    EXPECT_EQ(s.camera.position, d.camera.position);
    EXPECT_EQ(s.camera.target, d.camera.target);
    EXPECT_EQ(s.camera.up, d.camera.up);
    EXPECT_EQ(s.camera.fovYDegrees, d.camera.fovYDegrees);
    EXPECT_EQ(s.camera.nearPlane, d.camera.nearPlane);
    EXPECT_EQ(s.camera.farPlane, d.camera.farPlane);
    EXPECT_EQ(s.camera.reversedZ, d.camera.reversedZ);
    EXPECT_EQ(s.camera.infiniteFar, d.camera.infiniteFar);
    EXPECT_EQ(s.light.type, d.light.type);
    EXPECT_EQ(s.light.direction, d.light.direction);
    EXPECT_EQ(s.light.intensity, d.light.intensity);
    EXPECT_EQ(s.light.innerConeAngleDegrees, d.light.innerConeAngleDegrees);
    EXPECT_EQ(s.light.outerConeAngleDegrees, d.light.outerConeAngleDegrees);
    EXPECT_EQ(s.light.range, d.light.range);
    EXPECT_EQ(s.light.radius, d.light.radius);
    EXPECT_EQ(s.light.shadowMapSize, d.light.shadowMapSize);
    EXPECT_EQ(s.medium.betaR, d.medium.betaR);
    EXPECT_EQ(s.medium.betaM, d.medium.betaM);
    EXPECT_EQ(s.medium.g, d.medium.g);
    EXPECT_EQ(s.medium.sigmaA, d.medium.sigmaA);
    EXPECT_EQ(s.medium.phase, d.medium.phase);
    EXPECT_EQ(s.medium.maxDistance, d.medium.maxDistance);
    EXPECT_EQ(s.skyColor, d.skyColor);
    EXPECT_EQ(s.ambient, d.ambient);
    EXPECT_EQ(s.exposure, d.exposure);
}

TEST_F(SceneFileTest, RelativePathsResolveAgainstTheSceneFilesFolder) {
    write("models/a.gltf", "");
    write("scenes/b.glb", "");
    const std::string file =
        write("scenes/s.json",
              R"({"gltf": "../models/a.gltf", "models": [{"gltf": "b.glb"}, {"gltf": ")" + kBox +
                  R"("}]})");
    // Run from elsewhere: the scene's own folder must decide, not the working directory.
    const fs::path before = fs::current_path();
    fs::current_path(fs::temp_directory_path());
    const host::SceneDesc s = host::loadSceneFile(file);
    fs::current_path(before);
    ASSERT_EQ(s.models.size(), 3u);
    EXPECT_EQ(s.models[0].path, (dir_ / "models" / "a.gltf").string());
    EXPECT_EQ(s.models[1].path, (dir_ / "scenes" / "b.glb").string());
    EXPECT_EQ(s.models[2].path, kBox);
}

TEST_F(SceneFileTest, ModelTransformsScaleThenRotateXYZThenTranslate) {
    const std::string file = write(
        "t.json", R"({"models": [
      {"gltf": ")" + kBox +
                      R"(", "translation": [1, 2, 3], "rotationDegrees": [90, 90, 0], "scale": 2},
      {"gltf": ")" + kBox +
                      R"(", "rotationDegrees": [0, 0, 90], "scale": [1, 2, 3]}]})");
    const host::SceneDesc s = host::loadSceneFile(file);
    ASSERT_EQ(s.models.size(), 2u);
    // (0,1,0) * 2 = (0,2,0); Rx(90): (x, y, z) -> (x, -z, y) gives (0,0,2); Ry(90):
    // (x, y, z) -> (z, y, -x) gives (2,0,0); + (1,2,3). Rotating Y first would give (1,2,5).
    expectVec3(apply(s.models[0].transform, {0, 1, 0}), {3, 2, 3}, 1e-5f);
    // (1,1,1) * (1,2,3) = (1,2,3); Rz(90): (x, y, z) -> (-y, x, z) gives (-2,1,3).
    expectVec3(apply(s.models[1].transform, {1, 1, 1}), {-2, 1, 3}, 1e-5f);
}

TEST_F(SceneFileTest, LoadSceneMeshesAppendsEveryModel) {
    const std::string file = write("m.json", R"({"gltf": ")" + kBox + R"(",
      "models": [{"gltf": ")" + kBox + R"(", "translation": [10, 0, 0]}]})");
    const host::MeshData m = host::loadSceneMeshes(host::loadSceneFile(file));
    EXPECT_EQ(m.vertices.size(), 48u);
    EXPECT_EQ(m.indices.size(), 72u);
    ASSERT_EQ(m.primitives.size(), 2u);
    EXPECT_EQ(m.primitives[1].material, 1);
    EXPECT_EQ(m.textures.size(), 2u);
    expectVec3(m.bounds.min, {-0.5f, -0.5f, -0.5f}, kParsed);
    expectVec3(m.bounds.max, {10.5f, 0.5f, 0.5f}, kParsed);
}

// Every SCENE.json in `folder` loads with its meshes, and there is at least one: a folder with
// none (or none at all) fails rather than passing on nothing.
void expectScenesLoad(const fs::path& folder) {
    ASSERT_TRUE(fs::is_directory(folder)) << folder << " is not a folder";
    size_t loaded = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        EXPECT_NO_THROW(host::loadSceneMeshes(host::loadSceneFile(entry.path().string())));
        ++loaded;
    }
    EXPECT_GT(loaded, 0u) << "no scene files in " << folder;
}

TEST_F(SceneFileTest, ShippedScenesLoad) {
    expectScenesLoad(fs::path(LS_SOURCE_DIR) / "scenes");
}

// EXPECT_NONFATAL_FAILURE's statement may not name a local variable.
fs::path gEmptyFolder;

TEST_F(SceneFileTest, ShippedScenesCheckFailsOnAnEmptyFolder) {
    gEmptyFolder = dir_ / "empty scenes";
    fs::create_directories(gEmptyFolder);
    EXPECT_NONFATAL_FAILURE(expectScenesLoad(gEmptyFolder), "no scene files in");
}

TEST_F(SceneFileTest, FilesThatCannotBeRead) {
    const std::string missing = (dir_ / "missing.json").string();
    try {
        host::loadSceneFile(missing);
        FAIL() << "no error";
    } catch (const host::SceneError& e) {
        EXPECT_EQ(std::string(e.what()), missing + ": scene file does not exist");
    }
    EXPECT_EQ(errorFor(R"({"camera": })"),
              "malformed JSON at byte 12: [json.exception.parse_error.101] parse error at line 1, "
              "column 12: syntax error while parsing value - unexpected '}'; expected '[', '{', or "
              "a literal");
    EXPECT_EQ(errorFor(R"({"camera": {"near": 1e400}})"),
              "malformed JSON: [json.exception.out_of_range.406] number overflow parsing '1e400'");
    EXPECT_EQ(errorFor("[1, 2]"), "the top level must be a JSON object");
    EXPECT_EQ(errorFor(R"({"camera": {}, "camera": {}})"),
              "key 'camera' appears twice in one object");
}

// The message loadSceneFile throws for the file at `file`, whole.
std::string sceneErrorOf(const std::string& file) {
    try {
        host::loadSceneFile(file);
    } catch (const host::SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

// A path that never ends (a device, a FIFO) used to hang and eat memory; a directory or a huge
// file must be refused before anything is read.
TEST_F(SceneFileTest, OnlyRegularFilesUpToTheCapAreRead) {
    EXPECT_EQ(sceneErrorOf("/dev/zero"),
              "/dev/zero: scene file is a character device, not a regular file");
    EXPECT_EQ(sceneErrorOf(dir_.string()), dir_.string() + ": scene file is a directory");
    const std::string fifo = (dir_ / "fifo.json").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(sceneErrorOf(fifo), fifo + ": scene file is a pipe (FIFO), not a regular file");
    const std::string huge = write("huge.json", "{}");
    fs::resize_file(huge, (uintmax_t{16} << 20) + 1);  // sparse: nothing is written to disk
    EXPECT_EQ(sceneErrorOf(huge),
              huge + ": scene file is larger than the 16 MiB read for a scene file");
}

TEST_F(SceneFileTest, AGltfPathThatIsNotARegularFileSaysWhatItIs) {
    fs::create_directories(dir_ / "folder.gltf");
    EXPECT_EQ(
        errorFor(R"({"gltf": "folder.gltf"})"),
        "gltf 'folder.gltf' is a directory (looked for " + (dir_ / "folder.gltf").string() + ")");
    EXPECT_EQ(errorFor(R"({"models": [{"gltf": "/dev/zero"}]})"),
              "models[0].gltf '/dev/zero' is a character device, not a regular file (looked for "
              "/dev/zero)");
}

// Float overflow used to make a far camera look like an up vector parallel to the view.
TEST_F(SceneFileTest, AFarCameraIsReportedAsTooFar) {
    EXPECT_EQ(errorFor(R"({"camera": {"position": [1e20, 0, 0], "target": [0, 0, 0]}})"),
              "camera.position[0] = 1e+20: must be within +-1e+08 (the renderer works in single "
              "precision)");
    EXPECT_EQ(errorFor(R"({"camera": {"position": [0, 0, 0], "target": [0, 0, -3e38]}})"),
              "camera.target[2] = -3e+38: must be within +-1e+08 (the renderer works in single "
              "precision)");
    // Large but within the plugin's lightscatter::limits::kMaxLength: a valid camera.
    EXPECT_EQ(errorFor(R"({"camera": {"position": [1e8, 0, 0], "target": [-1e8, 0, 0], "far": 1e8,
                                   "reversedZ": true}})"),
              "(no error)");
    EXPECT_EQ(errorFor(R"({"light": {"direction": [1e20, 0, 0]}})"), "(no error)");
    EXPECT_EQ(errorFor(R"({"camera": {"up": [0, 1e30, 0]}})"), "(no error)");
}

// Values in range as written but not as the floats the plugin receives (1e-50 becomes 0) were
// refused later by the plugin, in its own field names.
TEST_F(SceneFileTest, ValuesAreCheckedAsTheFloatsTheyBecome) {
    EXPECT_EQ(errorFor(R"({"light": {"range": 1e-50}})"),
              "light.range = 1e-50: must be > 0 (it is 0 in single precision)");
    EXPECT_EQ(errorFor(R"({"exposure": 1e-46})"),
              "exposure = 1e-46: must be > 0 (it is 0 in single precision)");
    EXPECT_EQ(errorFor(R"({"camera": {"fovYDegrees": 177.000001}})"),
              "(no error)");  // 177 as a float
}

// The plugin's ranges (lightscatter.h, lightscatter::limits), refused before any device exists.
TEST_F(SceneFileTest, ThePluginsRangesAreTheScenesRanges) {
    EXPECT_EQ(errorFor(R"({"light": {"intensity": [1e10, 1, 1]}})"),
              "light.intensity[0] = 1e+10: must be in [0, 1e+09]");
    EXPECT_EQ(errorFor(R"({"lights": [{}, {"position": [0, -2e8, 0]}]})"),
              "lights[1].position[1] = -2e+08: must be in [-1e+08, 1e+08]");
    EXPECT_EQ(errorFor(R"({"light": {"radius": 1e-4}})"),
              "light.radius = 1e-04: must be in [0.001, 1e+08]");
    EXPECT_EQ(errorFor(R"({"light": {"halfAngleDegrees": 0.01}})"),
              "light.halfAngleDegrees = 0.01: must be in [0.1, 89]");
    EXPECT_EQ(errorFor(R"({"medium": {"betaM": [1, 3.4e38, 1]}})"),
              "medium.betaM[1] = 3.4e+38: must be in [0, 1000]");
    EXPECT_EQ(errorFor(R"({"medium": {"sigmaA": [0, 0, 2000]}})"),
              "medium.sigmaA[2] = 2000: must be in [0, 1000]");
    EXPECT_EQ(errorFor(R"({"medium": {"maxDistance": 1e9}})"),
              "medium.maxDistance = 1e+09: must be in (0, 1e+08]");
    EXPECT_EQ(errorFor(R"({"camera": {"fovYDegrees": 1e-20}})"),
              "camera.fovYDegrees = 1e-20: must be in [1e-04, 177]");
    EXPECT_EQ(errorFor(R"({"camera": {"far": 2e8}})"),
              "camera.far = 2e+08: must be at most 1e+08 unless camera.infiniteFar is true");
    EXPECT_EQ(errorFor(R"({"camera": {"near": 1e-30, "reversedZ": true}})"),
              "camera.near = 1e-30: must be in [1e-29, 1e+08]");
}

// Standard depth in the host's D32_SFLOAT buffer steps by 2^-24 near 1: the far plane (or the sky
// with an infinite far plane) may be at most 2^20 times the near plane. Reversed depth may not.
TEST_F(SceneFileTest, ANearPlaneTheDepthBufferCannotResolveIsRefused) {
    EXPECT_EQ(
        errorFor(R"({"camera": {"near": 1e-8, "far": 60}})"),
        "camera.near = 1e-08: with standard depth the far plane (camera.far, 60 m) may be at most "
        "1048576 times the near plane, where a float32 depth step is 1/16 of the distance; make "
        "camera.near 5.722046e-05 or more, or camera.reversedZ true");
    EXPECT_EQ(
        errorFor(
            R"({"camera": {"near": 1e-8, "infiniteFar": true}, "medium": {"maxDistance": 60}})"),
        "camera.near = 1e-08: with standard depth the sky (medium.maxDistance, 60 m) may be at "
        "most 1048576 times the near plane, where a float32 depth step is 1/16 of the distance; "
        "make camera.near 5.722046e-05 or more, or camera.reversedZ true");
    EXPECT_EQ(errorFor(R"({"camera": {"near": 1e-8, "far": 60, "reversedZ": true}})"),
              "(no error)");
    EXPECT_EQ(errorFor(R"({"camera": {"near": 1e-8, "reversedZ": true, "infiniteFar": true}})"),
              "(no error)");
    EXPECT_EQ(errorFor(R"({"camera": {"near": 1e-4, "far": 100}})"), "(no error)");
}

TEST_F(SceneFileTest, UnknownKeysAreRefusedWithTheKnownOnes) {
    EXPECT_EQ(errorFor(R"({"camra": {}})"),
              "unknown key 'camra' (known keys: gltf, models, camera, light, lights, "
              "lightsFromGltf, gltfLightScale, gltfLightShadows, medium, sky, ambient, "
              "exposure)");
    EXPECT_EQ(
        errorFor(R"({"camera": {"fov": 60}})"),
        "camera: unknown key 'fov' (known keys: position, target, up, fovYDegrees, near, far, "
        "reversedZ, infiniteFar)");
    EXPECT_EQ(errorFor(R"({"light": {"kind": "spot"}})"),
              "light: unknown key 'kind' (known keys: type, position, direction, intensity, "
              "innerConeAngleDegrees, outerConeAngleDegrees, halfAngleDegrees, range, "
              "rangeFalloff, radius, shadowMapSize, cookie)");
    EXPECT_EQ(
        errorFor(R"({"medium": {"beta": 1}})"),
        "medium: unknown key 'beta' (known keys: betaR, betaM, g, sigmaA, phase, maxDistance, "
        "density, heightFog, fogVolumes)");
    EXPECT_EQ(errorFor(R"({"sky": {"colour": [0, 0, 0]}})"),
              "sky: unknown key 'colour' (known keys: color)");
    EXPECT_EQ(errorFor(R"({"models": [{"gltf": ")" + kBox + R"(", "rotation": [0, 0, 0]}]})"),
              "models[0]: unknown key 'rotation' (known keys: gltf, translation, rotationDegrees, "
              "scale)");
}

TEST_F(SceneFileTest, WrongTypes) {
    EXPECT_EQ(errorFor(R"({"camera": []})"), "camera must be an object");
    EXPECT_EQ(errorFor(R"({"camera": {"position": "here"}})"),
              "camera.position must be an array of 3 numbers");
    EXPECT_EQ(errorFor(R"({"camera": {"position": [1, 2]}})"),
              "camera.position must be an array of 3 numbers");
    EXPECT_EQ(errorFor(R"({"camera": {"target": [1, "2", 3]}})"),
              "camera.target must be an array of 3 numbers");
    EXPECT_EQ(errorFor(R"({"camera": {"near": "0.1"}})"), "camera.near must be a number");
    EXPECT_EQ(errorFor(R"({"camera": {"reversedZ": 1}})"),
              "camera.reversedZ must be true or false");
    EXPECT_EQ(errorFor(R"({"light": {"type": 3}})"), "light.type must be a string");
    EXPECT_EQ(errorFor(R"({"gltf": 3})"), "gltf must be a string");
    EXPECT_EQ(errorFor(R"({"models": {}})"), "models must be an array of objects");
    EXPECT_EQ(errorFor(R"({"models": [3]})"), "models[0] must be an object");
    EXPECT_EQ(errorFor(R"({"models": [{}]})"), "models[0].gltf is required");
    EXPECT_EQ(errorFor(R"({"models": [{"gltf": ")" + kBox + R"(", "scale": "big"}]})"),
              "models[0].scale must be a number or an array of 3 numbers");
    EXPECT_EQ(errorFor(R"({"light": {"shadowMapSize": 1024.5}})"),
              "light.shadowMapSize must be an integer");
}

TEST_F(SceneFileTest, NamesAndPaths) {
    EXPECT_EQ(errorFor(R"({"light": {"type": "laser"}})"),
              "light.type 'laser' is not one of directional, spot, point");
    EXPECT_EQ(errorFor(R"({"medium": {"phase": "henyey-greenstein"}})"),
              "medium.phase 'henyey-greenstein' is not one of cornette-shanks, isotropic, hazy");
    EXPECT_EQ(errorFor(R"({"gltf": ""})"), "gltf must not be empty");
    EXPECT_EQ(errorFor(R"({"gltf": "nope.gltf"})"),
              "gltf 'nope.gltf' does not exist (looked for " + (dir_ / "nope.gltf").string() + ")");
    EXPECT_EQ(errorFor(R"({"models": [{"gltf": "../nope.glb"}]})"),
              "models[0].gltf '../nope.glb' does not exist (looked for " +
                  (dir_.parent_path() / "nope.glb").string() + ")");
}

TEST_F(SceneFileTest, NumbersOutOfRange) {
    EXPECT_EQ(errorFor(R"({"camera": {"fovYDegrees": 190}})"),
              "camera.fovYDegrees = 190: must be in [1e-04, 177]");
    EXPECT_EQ(errorFor(R"({"camera": {"fovYDegrees": 180}})"),
              "camera.fovYDegrees = 180: must be in [1e-04, 177]");
    EXPECT_EQ(errorFor(R"({"camera": {"fovYDegrees": 0}})"),
              "camera.fovYDegrees = 0: must be in [1e-04, 177]");
    EXPECT_EQ(errorFor(R"({"medium": {"g": 1.2}})"), "medium.g = 1.2: must be in (-1, 1)");
    EXPECT_EQ(errorFor(R"({"medium": {"g": -1}})"), "medium.g = -1: must be in (-1, 1)");
    EXPECT_EQ(errorFor(R"({"light": {"halfAngleDegrees": 0}})"),
              "light.halfAngleDegrees = 0: must be in [0.1, 89]");
    EXPECT_EQ(errorFor(R"({"light": {"halfAngleDegrees": 89.5}})"),
              "light.halfAngleDegrees = 89.5: must be in [0.1, 89]");
    EXPECT_EQ(errorFor(R"({"camera": {"near": 0}})"), "camera.near = 0: must be in [1e-29, 1e+08]");
    EXPECT_EQ(errorFor(R"({"camera": {"near": -0.1}})"),
              "camera.near = -0.1: must be in [1e-29, 1e+08]");
    EXPECT_EQ(errorFor(R"({"camera": {"near": 2, "far": 1.5}})"),
              "camera.far = 1.5: must be > camera.near (2) unless camera.infiniteFar is true");
    EXPECT_EQ(errorFor(R"({"camera": {"near": 0.1, "far": 0.1}})"),
              "camera.far = 0.1: must be > camera.near (0.1) unless camera.infiniteFar is true");
    EXPECT_EQ(errorFor(R"({"camera": {"far": 1e39}})"),
              "camera.far = 1e+39: must be a finite number");
    EXPECT_EQ(errorFor(R"({"camera": {"position": [0, -1e39, 0]}})"),
              "camera.position[1] = -1e+39: must be a finite number");
    EXPECT_EQ(errorFor(R"({"light": {"shadowMapSize": 16385}})"),
              "light.shadowMapSize = 16385: must be in [0, 16384]");
    EXPECT_EQ(errorFor(R"({"light": {"shadowMapSize": -1}})"),
              "light.shadowMapSize = -1: must be in [0, 16384]");
    EXPECT_EQ(errorFor(R"({"light": {"range": 0}})"), "light.range = 0: must be > 0");
    EXPECT_EQ(errorFor(R"({"light": {"radius": -0.05}})"),
              "light.radius = -0.05: must be in [0.001, 1e+08]");
    EXPECT_EQ(errorFor(R"({"medium": {"maxDistance": 0}})"),
              "medium.maxDistance = 0: must be in (0, 1e+08]");
    EXPECT_EQ(errorFor(R"({"exposure": -2})"), "exposure = -2: must be > 0");
    EXPECT_EQ(errorFor(R"({"models": [{"gltf": ")" + kBox + R"(", "scale": [1, 0, 1]}]})"),
              "models[0].scale = 0: must not be 0 (it flattens the model)");
}

TEST_F(SceneFileTest, NegativeCoefficients) {
    EXPECT_EQ(errorFor(R"({"medium": {"betaR": [1e-5, -1e-5, 0]}})"),
              "medium.betaR[1] = -1e-05: must be in [0, 1000]");
    EXPECT_EQ(errorFor(R"({"medium": {"betaM": [-0.5, 0, 0]}})"),
              "medium.betaM[0] = -0.5: must be in [0, 1000]");
    EXPECT_EQ(errorFor(R"({"medium": {"sigmaA": [0, 0, -2]}})"),
              "medium.sigmaA[2] = -2: must be in [0, 1000]");
    EXPECT_EQ(errorFor(R"({"light": {"intensity": [1, -1, 1]}})"),
              "light.intensity[1] = -1: must be in [0, 1e+09]");
    EXPECT_EQ(errorFor(R"({"sky": {"color": [0, 0, -0.25]}})"),
              "sky.color[2] = -0.25: must be >= 0");
    EXPECT_EQ(errorFor(R"({"ambient": [-3, 0, 0]})"), "ambient[0] = -3: must be >= 0");
}

TEST_F(SceneFileTest, Directions) {
    EXPECT_EQ(errorFor(R"({"light": {"direction": [0, 0, 0]}})"),
              "light.direction has zero length");
    EXPECT_EQ(errorFor(R"({"camera": {"up": [0, 0, 0]}})"), "camera.up has zero length");
    EXPECT_EQ(errorFor(R"({"camera": {"position": [1, 1, 1], "target": [1, 1, 1]}})"),
              "camera.target equals camera.position: the view direction has zero length");
    EXPECT_EQ(errorFor(R"({"camera": {"position": [0, 0, 0], "target": [0, 5, 0]}})"),
              "camera.up is parallel to the view direction");
}

// "lights": an array of light objects beside the single "light", one of the two.
// A spot's cookie: an image next to the scene (or at a path relative to it), decoded to RGBA8 as
// stored; every way it can be wrong is one line naming the field and the file.
TEST_F(SceneFileTest, ASpotsCookieIsAnImageRelativeToTheScene) {
    const fs::path png = fs::path(LS_SOURCE_DIR) / "scenes" / "stained_glass_cookie.png";
    fs::create_directories(dir_ / "glass");
    fs::copy_file(png, dir_ / "glass" / "pane.png");
    const std::string file = write("cookie.json", R"({"light": {"type": "spot", "shadowMapSize": 0,
        "cookie": "glass/pane.png"}})");
    const host::SceneDesc s = host::loadSceneFile(file);
    ASSERT_TRUE(s.light.cookie);
    EXPECT_EQ(s.light.cookie->width, 256u);
    EXPECT_EQ(s.light.cookie->height, 256u);
    EXPECT_EQ(s.light.cookie->rgba.size(), 256u * 256u * 4u);
    EXPECT_EQ(s.light.cookie->rgba[3], 255);  // RGB file: opaque
    EXPECT_EQ(s.light.cookie->name, (dir_ / "glass" / "pane.png").string());
    EXPECT_FALSE(
        host::loadSceneFile(write("none.json", R"({"light": {"type": "spot"}})")).light.cookie);

    EXPECT_EQ(errorFor(R"({"light": {"type": "spot", "cookie": "missing.png"}})"),
              "light.cookie 'missing.png' does not exist (looked for " +
                  (dir_ / "missing.png").string() + ")");
    write("text.png", "not a PNG at all");
    EXPECT_EQ(errorFor(R"({"light": {"type": "spot", "cookie": "text.png"}})"),
              "light.cookie 'text.png' is not an image the host reads: not an image stb_image "
              "reads: unknown image type");
    EXPECT_EQ(errorFor(R"({"light": {"type": "spot", "cookie": 3}})"),
              "light.cookie must be a string");
    EXPECT_EQ(errorFor(R"({"lights": [{"type": "spot"}, {"type": "point", "cookie": "x.png"}]})"),
              "lights[1].cookie needs a spot light (its cone's projection casts the image; a "
              "point light has no single projection, and the host fits a sun's shadow map to "
              "the view, which would slide a cookie with the camera)");
}

TEST_F(SceneFileTest, ALightListGivesEveryLight) {
    const std::string file = write("lights.json", R"({"lights": [
        {"type": "directional", "direction": [0, -1, 0], "shadowMapSize": 512},
        {"type": "spot", "position": [1, 5, 0], "halfAngleDegrees": 20, "shadowMapSize": 256},
        {"type": "point", "position": [0, 2, 0]}]})");
    const host::SceneDesc s = host::loadSceneFile(file);
    EXPECT_TRUE(s.lightList);
    ASSERT_EQ(s.lightCount(), 3u);
    EXPECT_EQ(s.light.type, lightscatter::LightType::Directional);
    EXPECT_EQ(s.lightAt(1).type, lightscatter::LightType::Spot);
    EXPECT_EQ(s.lightAt(1).shadowMapSize, 256u);
    EXPECT_FLOAT_EQ(s.lightAt(1).outerConeAngleDegrees, 20.0f);
    EXPECT_EQ(s.lightAt(2).type, lightscatter::LightType::Point);
    EXPECT_EQ(s.lightAt(2).shadowMapSize, 0u);
}

// A spot's cone as KHR_lights_punctual gives it, the former halfAngleDegrees as a hard cone, and a
// range's falloff (issue #25).
TEST_F(SceneFileTest, ConesAndRangesAsEnginesDefineThem) {
    const std::string file = write("cones.json", R"({"lights": [
        {"type": "spot", "innerConeAngleDegrees": 20, "outerConeAngleDegrees": 30},
        {"type": "spot", "halfAngleDegrees": 25},
        {"type": "spot", "outerConeAngleDegrees": 35},
        {"type": "point", "range": 12, "rangeFalloff": "window"}]})");
    const host::SceneDesc s = host::loadSceneFile(file);
    EXPECT_FLOAT_EQ(s.lightAt(0).innerConeAngleDegrees, 20.0f);
    EXPECT_FLOAT_EQ(s.lightAt(0).outerConeAngleDegrees, 30.0f);
    EXPECT_FLOAT_EQ(s.lightAt(1).innerConeAngleDegrees, 25.0f);
    EXPECT_FLOAT_EQ(s.lightAt(1).outerConeAngleDegrees, 25.0f);
    EXPECT_FLOAT_EQ(s.lightAt(2).innerConeAngleDegrees, 35.0f);  // without an inner: hard
    EXPECT_EQ(s.lightAt(2).rangeFalloff, lightscatter::RangeFalloff::Cut);
    EXPECT_FLOAT_EQ(s.lightAt(3).range, 12.0f);
    EXPECT_EQ(s.lightAt(3).rangeFalloff, lightscatter::RangeFalloff::Window);

    EXPECT_EQ(errorFor(R"({"light": {"halfAngleDegrees": 20, "outerConeAngleDegrees": 30}})"),
              "light: halfAngleDegrees is a hard cone, inner = outer: give it or "
              "innerConeAngleDegrees and outerConeAngleDegrees, not both");
    EXPECT_EQ(errorFor(R"({"light": {"innerConeAngleDegrees": 40, "outerConeAngleDegrees": 30}})"),
              "light.innerConeAngleDegrees = 40: must be at most outerConeAngleDegrees (30)");
    EXPECT_EQ(errorFor(R"({"light": {"rangeFalloff": "smooth"}})"),
              "light.rangeFalloff 'smooth' is not one of cut, window");
}

TEST_F(SceneFileTest, ALightListHasItsOwnRules) {
    EXPECT_EQ(errorFor(R"({"light": {"type": "spot"}, "lights": [{"type": "spot"}]})"),
              "\"light\" and \"lights\" are both given: a scene has one light (\"light\") or a "
              "list of them "
              "(\"lights\"), never both");
    EXPECT_EQ(errorFor(R"({"lights": []})"), "lights must be a non-empty array of light objects");
    EXPECT_EQ(errorFor(R"({"lights": {"type": "spot"}})"),
              "lights must be a non-empty array of light objects");
    EXPECT_EQ(errorFor(R"({"lights": [{"type": "spot"}, 3]})"), "lights[1] must be an object");
    EXPECT_EQ(
        errorFor(R"({"lights": [{"type": "spot"}, {"type": "spot", "halfAngleDegrees": 95}]})")
            .rfind("lights[1].halfAngleDegrees", 0),
        0u);
    EXPECT_EQ(errorFor(R"({"lights": [{"type": "spot"}, {"type": "spot", "colour": 1}]})")
                  .rfind("lights[1]: unknown key 'colour'", 0),
              0u);
    // A point light with a cube shadow map is taken alone and among others.
    EXPECT_EQ(errorFor(R"({"lights": [{"type": "point", "shadowMapSize": 64}]})"), "(no error)");
    EXPECT_EQ(errorFor(R"({"lights": [{"type": "spot"}, {"type": "point", "shadowMapSize": 64},
                                      {"type": "point", "shadowMapSize": 32}]})"),
              "(no error)");
}

// A 200 KB value of `levels` arrays within one another.
std::string deepArray(size_t levels) {
    return std::string(levels, '[') + std::string(levels, ']');
}

// Deep nesting is refused while parsing, in every field, and no message quotes more than a few
// dozen characters of what the file holds (scene files used to refuse these through type checks;
// now the parser does, as for the settings and benchmark files).
TEST_F(SceneFileTest, DeepNestingAndLongValuesGiveShortErrors) {
    for (size_t levels : {size_t{30000}, size_t{100000}}) {
        SCOPED_TRACE(levels);
        for (const std::string field : {"camera", "models", "lights", "exposure"}) {
            const std::string m = errorFor("{\"" + field + "\": " + deepArray(levels) + "}");
            EXPECT_EQ(m.rfind(field + "[0][0]", 0), 0u) << m;
            EXPECT_NE(m.find("arrays and objects nest more than 64 deep"), std::string::npos) << m;
            EXPECT_LE(m.size(), 200u) << m;
        }
    }
    const std::string key(100000, 'k');
    const std::string unknown = errorFor("{\"" + key + "\": 1}");
    EXPECT_EQ(unknown.rfind("unknown key 'kkkk", 0), 0u) << unknown;
    EXPECT_LE(unknown.size(), 300u) << unknown;
    const std::string phase =
        errorFor(R"({"medium": {"phase": ")" + std::string(100000, 'p') + "\"}}");
    EXPECT_EQ(phase.rfind("medium.phase 'ppp", 0), 0u) << phase;
    EXPECT_LE(phase.size(), 200u) << phase;
    const std::string path = errorFor(R"({"gltf": ")" + std::string(100000, 'g') + "\"}");
    EXPECT_EQ(path.rfind("gltf 'ggg", 0), 0u) << path;
    EXPECT_NE(path.find("is not a path: longer than the 4096 bytes Linux opens"), std::string::npos)
        << path;
    EXPECT_LE(path.size(), 200u) << path;
    EXPECT_EQ(errorFor(R"({"gltf": "box.gltf\u0000.txt"})"),
              "gltf 'box.gltf\\u0000.txt' is not a path: it holds a NUL character");
    EXPECT_EQ(errorFor(R"({"camera": {"near": 1, "near": 2}})"),
              "camera: key 'near' appears twice in one object");
}

}  // namespace
