// Errors that used to mislead (issue #8): inputs that never end, far cameras called "up is
// parallel", the plugin's field names and a doubled "lightscatter: " in scene errors, a directory
// glTF "not found", running out of host memory as a bare "std::bad_alloc".
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

using cli_test::expectFailure;
using cli_test::path;
using cli_test::run;
using cli_test::scene;
using cli_test::writeFile;

namespace {

// A scene in scratch() around the atrium's glTF, with the given top-level fields.
std::string sceneWith(const std::string& name, const std::string& json) {
    const std::string gltf = std::string(LS_SOURCE_DIR) + "/scenes/atrium.gltf";
    writeFile(name, "{\"gltf\": \"" + gltf + "\", " + json + "}");
    return name;
}

}  // namespace

TEST(CliErrors, InputsThatAreNotRegularFilesAreRefusedAtOnce) {
    expectFailure(run("render /dev/zero"),
                  "/dev/zero: scene file is a character device, not a regular file");
    expectFailure(run("render " + cli_test::scratch()), "scene file is a directory");
    std::filesystem::create_directories(path("folder.gltf"));
    writeFile("dir.json", R"({"gltf": "folder.gltf"})");
    expectFailure(run("render dir.json"), "dir.json: gltf 'folder.gltf' is a directory");
    writeFile("zero.json", R"({"gltf": "/dev/zero"})");
    expectFailure(run("render zero.json"),
                  "gltf '/dev/zero' is a character device, not a regular file");
    expectFailure(run("bench --config /dev/zero"),
                  "/dev/zero: benchmark configuration is a character device");
    expectFailure(run("render " + scene("atrium") + " --settings /dev/zero"),
                  "/dev/zero: settings file is a character device");
}

TEST(CliErrors, AFarCameraIsCalledFar) {
    const std::string s =
        sceneWith("far.json", R"("camera": {"position": [1e20, 0, 0], "target": [0, 0, 0]})");
    expectFailure(run("render " + s),
                  "far.json: camera.position[0] = 1e+20: must be within +-1e+08");
}

TEST(CliErrors, SceneValuesTheFloatsLoseAreNamedInTheScenesTerms) {
    const std::string angle =
        sceneWith("angle.json",
                  R"("light": {"type": "spot", "position": [0, 4, 0], "halfAngleDegrees": 1e-50})");
    expectFailure(run("render " + angle + " --size 8x8"),
                  "angle.json: light.halfAngleDegrees = 1e-50");
    const std::string near = sceneWith("near.json", R"("camera": {"near": 1e-50})");
    const auto r = run("render " + near + " --size 8x8");
    expectFailure(r, "near.json: camera.near = 1e-50");
    EXPECT_EQ(r.out.find("nearPlane"), std::string::npos) << r.out;
}

TEST(CliErrors, OutOfHostMemorySaysWhatRanOutWhileDoingWhat) {
    // 44739242 vertices in a 512 MiB buffer (a sparse file: no disk space): the buffer and 512 MiB
    // of positions read from it, under a 0.9 GB limit. (An accessor without a buffer view, zeros
    // the file does not hold, is capped before it can run out of anything.)
    constexpr uint64_t kBin = 512ull << 20;
    constexpr uint64_t kCount = kBin / 12;
    writeFile("huge.bin", "");
    std::filesystem::resize_file(path("huge.bin"), kBin);
    const nlohmann::json gltf = {
        {"asset", {{"version", "2.0"}}},
        {"buffers", {{{"byteLength", kBin}, {"uri", "huge.bin"}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteLength", kCount * 12}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", kCount}, {"type", "VEC3"}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"scenes", {{{"nodes", {0}}}}},
        {"scene", 0}};
    writeFile("huge.gltf", gltf.dump());
    writeFile("huge.json", R"({"gltf": "huge.gltf"})");
    const auto r = run("render huge.json --size 8x8", "ulimit -v 900000 &&");
    expectFailure(r, "lightscatter: out of host memory (an allocation failed) while loading " +
                         path("huge.gltf"));
}

// A 200 KB value nested 100,000 deep made `budget --settings` exit 139 with no output (the error
// message's dump() of it overflowed the stack); 30,000 levels made a 60 KB "line".
TEST(CliErrors, DeepNestingInASettingsFileIsOneShortLine) {
    for (size_t levels : {size_t{30000}, size_t{100000}}) {
        SCOPED_TRACE(levels);
        writeFile("deep.json",
                  R"({"slices": )" + std::string(levels, '[') + std::string(levels, ']') + "}");
        const auto r = run("budget --settings deep.json");
        EXPECT_EQ(r.exitCode, 1) << r.out.substr(0, 300);
        expectFailure(r, "deep.json: slices[0][0][0]");
        EXPECT_NE(r.out.find("arrays and objects nest more than 64 deep here"), std::string::npos)
            << r.out.substr(0, 300);
        EXPECT_LT(r.out.size(), 300u) << r.out.substr(0, 300);
    }
}

TEST(CliErrors, DoubledPrefixIsGone) {
    const auto r =
        run("budget --shadow-map 1");  // the plugin's own message starts "lightscatter: "
    EXPECT_EQ(r.out.find("lightscatter: lightscatter:"), std::string::npos) << r.out;
}
