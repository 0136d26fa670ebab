// The command line against hostile input (issue #22), as a table: each row sets up files in a
// folder of its own, runs one command, and expects an exit code and words in its one line of
// output. Every file a row sets up must be byte for byte the same afterwards (nothing an input is
// overwritten), and no temporary is left behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <stb/stb_image_write.h>
#include "cli_runner.h"
#include "host_test_helpers.h"

namespace {

namespace fs = std::filesystem;

struct Row {
    const char* name;
    // File name (in the row's folder) -> its text; "@copy:PATH" copies PATH of the repository.
    std::vector<std::pair<std::string, std::string>> files;
    // Run in the row's folder; {src} is the repository, {scene:NAME} scenes/NAME.json.
    std::string arguments;
    int exitCode;
    std::string words;        // in the output, which is one line unless `oneLine` is false
    std::string prefix = "";  // e.g. xvfb-run for the window
    bool oneLine = true;
    std::vector<std::string> absent = {};  // files or folders the command must not have made
    std::string wrong = "";                // words the output must not hold (a wrong reason)
    size_t maxChars = 0;                   // the most characters the output may have (0: any)
};

const std::string kSrc = LS_SOURCE_DIR;

// The atrium's scene and every file it reads, copied: outputs aimed at them must be refused, and a
// broken rule then overwrites the copy, never the repository's own.
const std::vector<std::pair<std::string, std::string>> kAtriumCopy = {
    {"atrium.json", "@copy:scenes/atrium.json"},
    {"atrium.gltf", "@copy:scenes/atrium.gltf"},
    {"atrium.bin", "@copy:scenes/atrium.bin"},
    {"atrium_floor.png", "@copy:scenes/atrium_floor.png"}};

std::vector<std::pair<std::string, std::string>> with(
    std::vector<std::pair<std::string, std::string>> a,
    const std::vector<std::pair<std::string, std::string>>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

const std::string kXvfb = cli_test::xvfb();
// A disk that fills after 1 KiB (dash counts ulimit -f in 512-byte blocks); SIGXFSZ ignored, so the
// write fails with EFBIG rather than the signal ending the program.
const char* kFullDisk = "trap '' XFSZ; ulimit -f 2;";

// The stained-glass spot with its cookie at `cookie` (in the row's folder).
std::vector<std::pair<std::string, std::string>> cookieScene(const std::string& cookie) {
    return {{"glass.json", R"({"gltf": "{src}/scenes/window_room.gltf",
        "camera": {"position": [2.5, 1.4, 2.5], "target": [-2.0, 1.1, -2.0]},
        "light": {"type": "spot", "position": [-10.0, 4.2, -1.0],
                  "direction": [0.9257, -0.3703, -0.0771], "intensity": [3000, 2500, 1900],
                  "halfAngleDegrees": 22.0, "range": 25.0, "shadowMapSize": 256,
                  "cookie": ")" +
                               cookie + R"("}})"},
            {cookie, "@copy:scenes/stained_glass_cookie.png"}};
}
const std::vector<std::pair<std::string, std::string>> kGlassHere = cookieScene("glass.png");

// {src}: the source tree; {scene:name}: a shipped scene; {dir}: the row's own folder.
std::string expanded(std::string text, const std::string& dir = {}) {
    for (size_t at; (at = text.find("{src}")) != std::string::npos;) text.replace(at, 5, kSrc);
    for (size_t at; (at = text.find("{dir}")) != std::string::npos;) text.replace(at, 5, dir);
    for (size_t at; (at = text.find("{scene:")) != std::string::npos;) {
        const size_t end = text.find('}', at);
        text.replace(at, end + 1 - at, cli_test::scene(text.substr(at + 7, end - at - 7)));
    }
    return text;
}

// A glTF of `n` separate small triangles on a 5 m square (each its own part for the beam tree),
// its buffer inline as a data URI.
std::string separateTriangles(int n) {
    std::string bytes;
    auto put = [&](float f) { bytes.append(reinterpret_cast<const char*>(&f), 4); };
    const int side = static_cast<int>(std::ceil(std::sqrt(n)));
    for (int i = 0; i < n; ++i) {
        const float x = -2.5f + 5.0f * static_cast<float>(i % side) / static_cast<float>(side);
        const float z = -2.5f + 5.0f * static_cast<float>(i / side) / static_cast<float>(side);
        for (const auto& [dx, dz] : {std::pair{0.0f, 0.0f}, {0.01f, 0.0f}, {0.0f, 0.01f}}) {
            put(x + dx);
            put(1.0f);
            put(z + dz);
        }
    }
    static const char* kBase64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string b64;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t v = uint32_t(uint8_t(bytes[i])) << 16 |
                           uint32_t(i + 1 < bytes.size() ? uint8_t(bytes[i + 1]) : 0) << 8 |
                           uint32_t(i + 2 < bytes.size() ? uint8_t(bytes[i + 2]) : 0);
        b64 += kBase64[v >> 18 & 63];
        b64 += kBase64[v >> 12 & 63];
        b64 += i + 1 < bytes.size() ? kBase64[v >> 6 & 63] : '=';
        b64 += i + 2 < bytes.size() ? kBase64[v & 63] : '=';
    }
    const std::string count = std::to_string(3 * n), length = std::to_string(bytes.size());
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
           count + R"(, "type": "VEC3", "min": [-2.5, 1, -2.5], "max": [2.51, 1, 2.51]}],
      "bufferViews": [{"buffer": 0, "byteLength": )" +
           length + R"(}], "buffers": [{"byteLength": )" + length +
           R"(, "uri": "data:application/octet-stream;base64,)" + b64 + R"("}]})";
}

using host_test::readAll;

// A PNG of `width` x `height` grey pixels, as bytes.
std::string png(int width, int height) {
    std::string out;
    const std::vector<unsigned char> pixels(size_t(width) * size_t(height) * 4, 128);
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            static_cast<std::string*>(context)->append(static_cast<char*>(data), size_t(size));
        },
        &out, width, height, 4, pixels.data(), width * 4);
    return out;
}

// The atrium with its floor's texture replaced by `image`.
std::vector<std::pair<std::string, std::string>> atriumWithFloor(const std::string& image) {
    std::string gltf = readAll(fs::path(kSrc) / "scenes/atrium.gltf");
    gltf.replace(gltf.find("atrium_floor.png"), 16, "floor.png");
    return {{"atrium.json", "@copy:scenes/atrium.json"},
            {"atrium.gltf", gltf},
            {"atrium.bin", "@copy:scenes/atrium.bin"},
            {"floor.png", image}};
}

// {"KEY": [[[...]]]} nested `depth` deep.
std::string nested(const std::string& key, int depth) {
    return "{\"" + key + "\": " + std::string(size_t(depth), '[') +
           std::string(size_t(depth), ']') + "}";
}

// A 36-byte triangle whose positions' accessor claims `count` elements (a glTF of about 430 bytes).
std::string hugeCount(uint32_t count) {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
           std::to_string(count) + R"(, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";
}

std::string repeated(const std::string& word, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += (i ? "," : "") + word;
    return out;
}

std::string manyLights(int n) {
    std::string lights;
    for (int i = 0; i < n; ++i)
        lights += std::string(i ? ", " : "") + R"({"type": "spot", "position": [)" +
                  std::to_string(i % 8) +
                  R"(, 4, 0], "direction": [0, -1, 0], "shadowMapSize": 0})";
    return R"({"lights": [)" + lights + "]}";
}

const char* kUnderASpot =
    R"({"gltf": "many.gltf", "camera": {"position": [0, 3, 6], "target": [0, 1, 0]},
    "light": {"type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "halfAngleDegrees": 40,
              "shadowMapSize": 256}, "medium": {"betaM": [0.05, 0.05, 0.05]}})";

// `n` empty objects in one array: {"KEY": [{},{},...]} (3 MB at a million).
std::string emptyObjects(const std::string& key, size_t n) {
    std::string out = "{\"" + key + "\": [";
    for (size_t i = 0; i < n; ++i) out += i ? ",{}" : "{}";
    return out + "]}";
}

// A glTF of `n` nodes, each named and moved, none with a mesh (18 MB at 400,000).
std::string manyNodes(size_t n) {
    std::string nodes;
    for (size_t i = 0; i < n; ++i)
        nodes += std::string(i ? "," : "") + R"({"name": "n)" + std::to_string(i) +
                 R"(", "translation": [1, 2, 3]})";
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [)" +
           nodes + "]}";
}

// The first bytes of a PNG of `width` x `height` pixels: its signature and IHDR chunk, enough for
// its size to be read (a 20000x20000 image would take 1.6 GB to write).
std::string pngHeader(uint32_t width, uint32_t height) {
    std::string out = "\x89PNG\r\n\x1a\n";
    auto u32 = [&](uint32_t v) {
        for (int shift = 24; shift >= 0; shift -= 8) out += char((v >> shift) & 0xFF);
    };
    u32(13);
    out += "IHDR";
    u32(width);
    u32(height);
    out += std::string("\x08\x06\x00\x00\x00", 5);  // 8-bit RGBA, no interlace
    u32(0);                                         // the CRC, which the size does not need
    return out + std::string(64, '\0');
}

// The atrium with its buffer named by an absolute URI (the row's folder, {dir}), read from a
// folder below the one it is in.
std::vector<std::pair<std::string, std::string>> atriumWithAbsoluteBuffer() {
    std::string gltf = readAll(fs::path(kSrc) / "scenes/atrium.gltf");
    gltf.replace(gltf.find("\"atrium.bin\""), 12, "\"{dir}/atrium.bin\"");
    return {{"sub/atrium.json", "@copy:scenes/atrium.json"},
            {"sub/atrium.gltf", gltf},
            {"atrium.bin", "@copy:scenes/atrium.bin"},
            {"sub/atrium_floor.png", "@copy:scenes/atrium_floor.png"}};
}

std::vector<Row> rows() {
    return {
        // 1-4: no output replaces a file the command reads, or a file a scene beside it reads.
        {"MemoryLogIsTheScene", kAtriumCopy, "view atrium.json --frames 2 --memory-log atrium.json",
         1, "--memory-log atrium.json: is the scene file"},
        {"MemoryLogIsTheScenesBuffer", kAtriumCopy,
         "view atrium.json --frames 2 --memory-log atrium.bin", 1,
         "--memory-log atrium.bin: is a file the scene reads"},
        {"MemoryLogBeforeTheWindowFails", with(kAtriumCopy, {{"log.csv", "the previous log"}}),
         "view atrium.json --frames 2 --memory-log log.csv", 1, "cannot open a window",
         "env -u DISPLAY"},
        {"ScreenshotIsTheScenesTexture", kAtriumCopy,
         "view atrium.json --size 32x18 --frames 2 --screenshot atrium_floor.png", 1,
         "--screenshot atrium_floor.png: is a file the scene reads", kXvfb},
        {"BenchOutIsTheConfigurationsFolder",
         {{"D/bench.json", "@copy:bench/small.json"}},
         "bench --config D/bench.json --out D",
         1,
         "--out D/bench.json: is the benchmark configuration"},
        {"RenderOutIsAnotherScenesTexture", kAtriumCopy,
         "render {scene:window_room} --size 8x8 --out atrium_floor.png", 1,
         "--out atrium_floor.png: is a file that atrium.gltf reads"},
        {"RenderOutIsAnotherScenesBuffer", kAtriumCopy,
         "render {scene:window_room} --size 8x8 --timings atrium.bin", 1,
         "--timings atrium.bin: is a file that atrium.gltf reads"},
        {"RenderTimingsIsAnotherScene", kAtriumCopy,
         "render {scene:window_room} --size 8x8 --timings atrium.gltf", 1,
         "--timings atrium.gltf: is a file that atrium.json reads"},
        {"PatternOutIsASceneFile", kAtriumCopy, "pattern --size 8x8 --out atrium_floor.png", 1,
         "--out atrium_floor.png: is a file that"},

        // The scan of an output's folder for the files its scenes read survives what it finds
        // there.
        {"AnOutputBesideDeeplyNestedFiles",
         {{"evil.json", nested("gltf", 100000)}, {"evil.gltf", nested("buffers", 100000)}},
         "render {scene:window_room} --size 8x8 --out o.png",
         0,
         "o.png: 8x8",
         "",
         false},

        // 14: a benchmark that cannot run, or would measure nothing, is refused before the first
        // run.
        {"BenchMethodThatCannotTakeALight",
         {{"pair.json", R"({"gltf": "{src}/scenes/point_cage.gltf", "lights": [
                        {"type": "point", "position": [0, 3, 0]},
                        {"type": "point", "position": [0, 2, 0], "shadowMapSize": 64}]})"},
          {"b.json", R"({"frames": 1, "warmup": 0, "size": "16x16", "measureError": false,
                        "scenes": ["{dir}/pair.json"], "methods": ["epipolar", "analytic"]})"}},
         "bench --config b.json --out results",
         1,
         "pair.json: the plugin refused the frame: method analytic cannot sample a point light's "
         "cube shadow map (lights[1].shadowMapSize",
         "",
         true,
         {"results"}},
        {"BenchWithoutMethods",
         {{"b.json", R"({"scenes": ["{scene:atrium}"], "methods": []})"}},
         "bench --config b.json --out results",
         1,
         "b.json: methods is empty",
         "",
         true,
         {"results"}},
        {"BenchWithoutProfiles",
         {{"b.json", R"({"scenes": ["{scene:atrium}"], "profiles": []})"}},
         "bench --config b.json --out results",
         1,
         "b.json: profiles is empty",
         "",
         true,
         {"results"}},
        {"BenchSceneWithoutMethods",
         {{"b.json", R"({"scenes": [{"scene": "{scene:atrium}", "methods": []}]})"}},
         "bench --config b.json --out results",
         1,
         "b.json: scenes[0].methods is empty",
         "",
         true,
         {"results"}},

        // 5: deeply nested JSON is refused while it is read, in one short line.
        {"DeepNestingInASettingsFile",
         {{"deep.json", nested("slices", 100000)}},
         "budget --settings deep.json",
         1,
         "deep.json: slices[0][0][0]"},
        {"DeepNestingInABenchmarkFile",
         {{"deep.json", nested("frames", 100000)}},
         "bench --config deep.json --out r",
         1,
         "arrays and objects nest more than 64 deep here",
         "",
         true,
         {"r"}},
        {"DeepNestingInASceneFile",
         {{"deep.json", nested("camera", 100000)}},
         "render deep.json --size 8x8",
         1,
         "arrays and objects nest more than 64 deep here"},

        // 6: a glTF accessor's count is checked against its view before anything is allocated.
        {"AnAccessorCountFarBeyondItsView",
         {{"count.gltf", hugeCount(268435456)}, {"count.json", R"({"gltf": "count.gltf"})"}},
         "render count.json --size 8x8",
         1,
         "accessor 0 reads past the end of buffer view 0: 268435456 elements of 12 bytes"},
        {"AnAccessorCountOfTwoToTheThirtyTwoLessOne",
         {{"count.gltf", hugeCount(4294967295u)}, {"count.json", R"({"gltf": "count.gltf"})"}},
         "render count.json --size 8x8",
         1,
         "accessor 0 reads past the end of buffer view 0: 4294967295 elements"},

        // 7: the list of lights has a stated limit, in the scene, the budget and the plugin.
        {"MoreLightsThanTheLimit",
         {{"many_lights.json", manyLights(65)}},
         "render many_lights.json --size 8x8",
         1,
         "many_lights.json: lights has 65 entries: at most 64 (the plugin's kMaxLights)"},
        {"ABudgetOfMoreLightsThanTheLimit",
         {},
         "budget --lights " + repeated("spot", 65),
         1,
         "budget lights: 65 lights: at most 64"},

        // 8: what the device cannot hold is refused naming the option or field, the size and what
        // the device has, before Vulkan is asked for it: vkGetPhysicalDeviceImageFormatProperties'
        // maxResourceSize (lavapipe's is 2^32 - 1 bytes) before vkCreateImage, the memory heap
        // (lavapipe's is 2 GiB) before vkAllocateMemory. With the validation layer forced on the
        // process, the one line shows that no image was created past the limit (issue #42:
        // UNASSIGNED-CoreValidation-Image-InvalidFormatLimitsViolation).
        {"AScreenLargerThanTheDeviceHolds",
         {},
         "render {scene:window_room} --size 16384x16384",
         1,
         "--size 16384x16384: image 'host in-scattering' (16384x16384 R32G32B32A32_SFLOAT) needs "
         "4294967296 bytes (4 GiB): the device takes at most 4294967295 bytes for one image of "
         "this format and usage (maxResourceSize, vkGetPhysicalDeviceImageFormatProperties)",
         "VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation"},
        {"AScreenLargerThanTheDeviceHasMemoryFor",
         {},
         "render {scene:window_room} --size 16384x11586",
         1,
         "--size 16384x11586: out of device memory: image 'host in-scattering' (16384x11586 "
         "R32G32B32A32_SFLOAT) needs 2.8 GiB; the device has 2 GiB in heap 0"},
        {"AGraphLargerThanTheDeviceHolds",
         {},
         "graph {scene:window_room} --dot --size 16384x16384",
         1,
         "--size 16384x16384: image 'host in-scattering' (16384x16384 R32G32B32A32_SFLOAT) needs "
         "4294967296 bytes"},
        {"ABenchmarkLargerThanTheDeviceHolds",
         {{"b.json", R"({"frames": 1, "warmup": 0, "size": "16384x16384", "measureError": false,
                        "scenes": ["{scene:window_room}"], "methods": ["brute-force"]})"}},
         "bench --config b.json --out results",
         1,
         "b.json: run 'brute-force' at size 16384x16384: image 'host in-scattering' "
         "(16384x16384 R32G32B32A32_SFLOAT) needs 4294967296 bytes",
         "",
         false},
        {"ACubeShadowMapLargerThanTheDeviceHolds",
         {{"cube.json",
           R"({"light": {"type": "point", "position": [0, 1, 0], "shadowMapSize": 16384}})"}},
         "render cube.json --size 16x16",
         1,
         "cube.json: light.shadowMapSize 16384: image 'host cube shadow map' (16384x16384 "
         "D32_SFLOAT, 6 layers) needs 6442450944 bytes (6 GiB): the device takes at most "
         "4294967295 bytes for one image of this format and usage (maxResourceSize",
         "VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation"},
        // A texture wider than a texture may be is read as unreadable: a warning, and its materials
        // keep their base color (the loader refuses it from the PNG's header; the device's own
        // maxImageDimension2D is checked again before any upload, DeviceMemoryGpu).
        {"ATextureWiderThanTheDeviceTakes", atriumWithFloor(png(16385, 1)),
         "render atrium.json --size 16x16 --out a.png --validation", 0,
         "image 0 'floor.png' could not be decoded (16385x1 pixels: a texture has 1 to 16384 a "
         "side); materials "
         "using it fall back to their base color factor",
         "", false},
        {"ATextureAsWideAsTheDeviceTakes", atriumWithFloor(png(16384, 1)),
         "render atrium.json --size 16x16 --out a.png --validation", 0, "a.png: 16x16", "", false},

        // 9: a scene of more parts than the beam tree takes renders with every method (occluders
        // are checked by the methods that read them, and the host merges them into a grid).
        {"ManyPartsRenderWithEpipolar",
         {{"many.gltf", separateTriangles(5000)}, {"many.json", kUnderASpot}},
         "render many.json --method epipolar --size 16x16",
         0,
         "many.png: 16x16, epipolar",
         "",
         false},
        {"ManyPartsRenderWithTheBeamTree",
         {{"many.gltf", separateTriangles(5000)}, {"many.json", kUnderASpot}},
         "render many.json --method beam-tree-analytic --size 16x16",
         0,
         "many.png: 16x16, beam-tree-analytic",
         "",
         false},

        // 10: every finite number renders finite values or is refused, naming the field and range.
        {"AnAmbientThePlanesCannotCarry",
         {{"amb.json", R"({"planeAmbient": 1e37})"}},
         "render {scene:window_room} --method planes --settings amb.json --size 16x16",
         1,
         "amb.json: planeAmbient = 1e+37: must be in [0, 1e+06]"},
        {"ACoefficientTheShadersCannotCarry",
         {{"fog.json", R"({"medium": {"betaM": [3.4e38, 3.4e38, 3.4e38]}})"}},
         "render fog.json --method cone-march --size 16x16",
         1,
         "fog.json: medium.betaM[0] = 3.4e+38: must be in [0, 1000]"},

        // 11: cameras single precision cannot represent are refused, the others render.
        {"ANearPlaneStandardDepthCannotHold",
         {{"near.json", R"({"camera": {"near": 1e-8}})"}},
         "render near.json --size 16x16",
         1,
         "near.json: camera.near = 1e-08: with standard depth the far plane (camera.far, 1000 m) "
         "may be at most "
         "1048576 times the near plane"},
        {"ANearPlaneReversedDepthHolds",
         {{"near.json", R"({"camera": {"near": 1e-8, "reversedZ": true}})"}},
         "render near.json --size 16x16",
         0,
         "near.png: 16x16",
         "",
         false},
        {"ANearPlaneReversedInfiniteDepthHolds",
         {{"near.json", R"({"camera": {"near": 1e-8, "reversedZ": true, "infiniteFar": true}})"}},
         "render near.json --size 16x16",
         0,
         "near.png: 16x16",
         "",
         false},
        {"AFieldOfViewTooNarrow",
         {{"fov.json", R"({"camera": {"fovYDegrees": 1e-20}})"}},
         "render fov.json --size 16x16",
         1,
         "fov.json: camera.fovYDegrees = 1e-20: must be in [1e-04, 177]"},

        // 12, 13: a low sun over a city 20 km deep, a cube-shadowed light on screen in a cage
        // (their
        // accuracy is the hard suite's).
        {"ALowSunOverACity",
         {},
         "render {src}/scenes/hard/low_sun_city.json --size 32x18 --method epipolar",
         0,
         "low_sun_city.png: 32x18, epipolar",
         "",
         false},
        {"APointLightInACageOnScreen",
         {},
         "render {src}/scenes/hard/point_in_cage.json --size 32x18 --method epipolar",
         0,
         "point_in_cage.png: 32x18, epipolar",
         "",
         false},

        // 15: an option's value never starts with "--"; "--" ends the options.
        {"AnOptionTakesNoOptionAsItsValue",
         {},
         "render {scene:atrium} --timings --out a.png --size 64x36",
         1,
         "option --timings needs a value, but the word after it is the option '--size'"},
        {"TwoDashesEndTheOptions",
         {{"--ddash.json", "{}"}},
         "render --size 8x8 --out d.png -- --ddash.json",
         0,
         "d.png: 8x8",
         "",
         false},
        {"ALightFartherThanSinglePrecisionReaches",
         {{"far.json",
           R"({"light": {"type": "spot", "position": [1e20, 4, 0], "direction": [0, -1, 0]}})"}},
         "render far.json --size 8x8",
         1,
         "far.json: light.position[0] = 1e+20: must be in [-1e+08, 1e+08]"},
        {"AListOfOneLightIsNamedAsTheList",
         {{"one.json",
           R"({"lights": [{"type": "point", "position": [0, 1, 0], "shadowMapSize": 64}]})"}},
         "render one.json --size 8x8 --method analytic",
         1,
         "one.json: the plugin refused the frame: method analytic cannot sample a point light's "
         "cube shadow map "
         "(lights[0].shadowMapSize > 0"},
        {"RenderNamesTheSceneThePluginRefuses",
         {},
         "render {scene:atrium_lights} --method analytic --size 8x8",
         1,
         "atrium_lights.json: the plugin refused the frame: lights[0]: method analytic"},
        {"GraphNamesTheSceneThePluginRefuses",
         {},
         "graph {scene:atrium_lights} --dot --method analytic",
         1,
         "atrium_lights.json: the plugin refused the frame: lights[0]: method analytic"},
        // Issue #42: the JSON reader is linear. A million objects in one array (3 MB) took over
        // 120 s to refuse, a 1 MiB settings file 19-30 s, a glTF of 400,000 nodes 27-41 s; each is
        // now read in one pass. Nothing is timed: read quadratically, the 9 MB of objects here
        // take about an hour, past ctest's timeout of 1500 s.
        {"MillionsOfObjectsInASceneAreRefusedInOnePass",
         {{"many.json", emptyObjects("lights", 3000000)}},
         "render many.json --size 8x8",
         1,
         "many.json: lights has 3000000 entries: at most 64 (the plugin's kMaxLights)"},
        {"AMebibyteSettingsFileOfObjects",
         {{"s.json", emptyObjects("x", 349000)}},
         "budget --settings s.json",
         1,
         "s.json: unknown key 'x'"},
        {"AMebibytePanelScriptOfObjects",
         {{"ps.json", "[" + repeated("{}", 349000) + ", 1]"}},
         "view {scene:engine_spot} --size 32x18 --frames 1 --panel-script ps.json",
         1,
         "ps.json: step 349000: must be an object",
         kXvfb},
        {"AMebibyteBenchmarkConfigurationOfObjects",
         {{"b.json", emptyObjects("x", 349000)}},
         "bench --config b.json --out r",
         1,
         "b.json: unknown key 'x'",
         "",
         true,
         {"r"}},
        {"AGltfOfFourHundredThousandNodes",
         {{"nodes.gltf", manyNodes(400000)}, {"nodes.json", R"({"gltf": "nodes.gltf"})"}},
         "render nodes.json --size 8x8",
         0,
         "nodes.png: 8x8",
         "",
         false},

        // Issue #42: a float field is compared with the floats nearest its bounds: each bound
        // as its table writes it is accepted (0.99f lies above 0.99, and was refused with
        // "must be in [0, 0.99]"); past it, the message quotes the bound applied.
        {"AHistoryWeightAtItsBound",
         {{"s.json", R"({"froxelHistoryWeight": 0.99})"}},
         "budget --method froxels --profile custom --settings s.json --size 64x36",
         0,
         "froxel",
         "",
         false,
         {},
         "must be in"},
        {"APlaneSpacingAtItsBound",
         {{"s.json", R"({"planeSpacing": 1e-6})"}},
         "budget --method planes --profile custom --settings s.json --size 64x36",
         0,
         "planes",
         "",
         false,
         {},
         "must be in"},
        // Its bound passes the field's range; the frame then wants it past the near plane.
        {"AFroxelFarDistanceAtItsBound",
         {{"s.json", R"({"froxelFarDistance": 1e-6})"}},
         "budget --method froxels --profile custom --settings s.json --size 64x36",
         1,
         "froxels.farDistance = 1e-06: must be beyond the camera's near plane (0.1)",
         "",
         true,
         {},
         "must be in"},
        {"APlaneRangeAtItsBound",
         {{"s.json", R"({"planeRange": 1e30})"}},
         "budget --method planes --profile custom --settings s.json --size 64x36",
         0,
         "planes",
         "",
         false,
         {},
         "must be"},
        // The per-pixel history refines the temporal mode; without it there is nothing to keep.
        {"APixelHistoryWithoutTheTemporalMode",
         {{"s.json", R"({"froxels": {"pixelHistory": true}})"}},
         "budget --method froxels --profile custom --settings s.json --size 64x36",
         1,
         "froxels.pixelHistory = true: needs froxels.temporal = true"},
        {"AHistoryWeightPastItsBound",
         {{"s.json", R"({"froxelHistoryWeight": 0.9900001})"}},
         "budget --method froxels --profile custom --settings s.json --size 64x36",
         1,
         "s.json: froxelHistoryWeight = 0.9900001: must be in [0, 0.99]"},
        // A benchmark's run past the bound, its 5,000-character label cut where it is quoted.
        {"ABenchmarkRunPastABoundWithALongLabel",
         {{"b.json", R"({"scenes": ["{scene:atrium}"], "configurations": [{"label": ")" +
                         std::string(5000, 'L') +
                         R"(", "method": "froxels", "froxels": {"historyWeight": 0.995}}]})"}},
         "bench --config b.json --out r",
         1,
         "froxels.historyWeight = 0.995: must be in [0, 0.99]",
         "",
         true,
         {"r"},
         "",
         400},

        // Issue #42: values the viewer saves read back; a panel script's integer past its field
        // was clamped to 4294967295 without a word.
        {"APanelScriptIntegerPastItsField",
         {{"ps.json", R"([{"settings": {"epipolar.fixupMaxSteps": 18446744073709551615}}])"}},
         "view {scene:engine_spot} --size 32x18 --frames 1 --panel-script ps.json",
         1,
         "ps.json: step 0: settings.epipolar.fixupMaxSteps = 18446744073709551615: must be a "
         "whole number from 0 to 4294967295",
         kXvfb},

        // Issue #42: a froxel preset wherever a method's name is taken.
        {"APanelScriptTakesAFroxelPreset",
         {{"ps.json", R"([{"method": "froxels-unreal"}, {"method": "froxels-hdrp"}])"}},
         "view {scene:engine_spot} --size 32x18 --frames 2 --panel-script ps.json",
         0,
         "",
         kXvfb,
         false,
         {},
         "not a method"},
        {"ABudgetLightTakesAFroxelPreset",
         {},
         "budget --lights spot:froxels-unreal --size 64x36",
         0,
         "froxel",
         "",
         false,
         {},
         "is not shadowed"},
        {"ABudgetOfTwoPresets",
         {},
         "budget --lights spot:froxels-unreal,point:froxels-hdrp --size 64x36",
         1,
         "--lights spot:froxels-unreal,point:froxels-hdrp: presets 'froxels-unreal' and "
         "'froxels-hdrp': one frame's lights share one set of settings, so one preset"},

        // Issue #42: every echo of input is cut and its control characters escaped (error lines
        // of 1,000,063 characters for a panel script's value, 200,161 for --lights).
        {"APanelScriptValueOfAMegabyte",
         {{"ps.json", R"([{"method": ")" + std::string(1000000, 'm') + R"("}])"}},
         "view {scene:engine_spot} --size 32x18 --frames 1 --panel-script ps.json",
         1,
         "ps.json: step 0: method = \"mmmm",
         kXvfb,
         true,
         {},
         "",
         400},
        {"ALongListOfLights",
         {},
         "budget --lights spot:" + std::string(100000, 'x'),
         1,
         "is not shadowed, unshadowed or a method's or a preset's name",
         "",
         true,
         {},
         "",
         600},
        {"AControlCharacterInAFileName",
         {},
         "render \"$(printf 't\\033]0;PWNED\\007.json')\" --size 8x8",
         1,
         "t\\u001b]0;PWNED\\u0007.json",
         "",
         true,
         {},
         "\x1b"},

        // Issue #42: the right reasons.
        {"ACookieOfTwentyThousandPixelsASide",
         {{"room.json", "@copy:scenes/stained_glass.json"},
          {"window_room.gltf", "@copy:scenes/window_room.gltf"},
          {"window_room.bin", "@copy:scenes/window_room.bin"},
          {"stained_glass_cookie.png", pngHeader(20000, 20000)}},
         "render room.json --size 8x8",
         1,
         "20000x20000 pixels: at most",
         "",
         true,
         {},
         "unknown image type"},
        {"AnAbsoluteBufferUri",
         atriumWithAbsoluteBuffer(),
         "render sub/atrium.json --size 8x8 --out a.png",
         0,
         "a.png: 8x8",
         "",
         false,
         {},
         "File not found"},
        {"NothingAfterTheFileName",
         {},
         "render --size 8x8 -- a.json b.json",
         1,
         "unexpected argument 'b.json' after \"--\""},

        // 42: the panel's saves follow the outputs' rules, checked before the first frame.
        {"PanelSaveOntoTheScene", with(kAtriumCopy, {{"ps.json", R"([{"save": "atrium.json"}])"}}),
         "view atrium.json --size 32x18 --frames 1 --panel-script ps.json", 1,
         "--panel-script ps.json: step 0 saves atrium.json: is the scene file", kXvfb},
        {"PanelSaveOntoTheGltf", with(kAtriumCopy, {{"ps.json", R"([{"save": "atrium.gltf"}])"}}),
         "view atrium.json --size 32x18 --frames 1 --panel-script ps.json", 1,
         "step 0 saves atrium.gltf: is a file the scene reads", kXvfb},
        {"PanelSaveOntoACookie", with(kGlassHere, {{"ps.json", R"([{"save": "glass.png"}])"}}),
         "view glass.json --size 32x18 --frames 1 --panel-script ps.json", 1,
         "step 0 saves glass.png: is a file the scene reads", kXvfb},
        {"PanelSaveOntoTheSettingsFile",
         with(kAtriumCopy, {{"s.json", "{}"}, {"ps.json", R"([{"save": "s.json"}])"}}),
         "view atrium.json --size 32x18 --frames 1 --profile custom --settings s.json "
         "--panel-script ps.json",
         1, "step 0 saves s.json: is the settings file", kXvfb},
        {"PanelSaveOntoItsScript", with(kAtriumCopy, {{"ps.json", R"([{"save": "ps.json"}])"}}),
         "view atrium.json --size 32x18 --frames 1 --panel-script ps.json", 1,
         "step 0 saves ps.json: is the panel script", kXvfb},
        {"PanelSaveOntoAnotherScene",
         with(kAtriumCopy,
              {{"other.json", R"({"gltf": "atrium.gltf", "light": {"type": "point"}})"},
               {"ps.json", R"([{"save": "other.json"}])"}}),
         "view atrium.json --size 32x18 --frames 1 --panel-script ps.json", 1,
         "save settings other.json: exists and is not a settings file", kXvfb},
        {"PanelSaveOntoADevice", with(kAtriumCopy, {{"ps.json", R"([{"save": "/dev/null"}])"}}),
         "view atrium.json --size 32x18 --frames 1 --panel-script ps.json", 1,
         "step 0 saves /dev/null: exists and is not a regular file", kXvfb},
        {"PanelSaveAfterTheLastFrame",
         with(kAtriumCopy, {{"ps.json", R"([{}, {"save": "s.json"}])"}}),
         "view atrium.json --size 32x18 --frames 1 --panel-script ps.json",
         1,
         "step 1 saves s.json, but --frames 1 ends before step 1 is made",
         kXvfb,
         true,
         {"s.json"}},
        {"PanelSaveOntoADirectory",
         with(kAtriumCopy, {{"d/keep", "mine"}, {"ps.json", R"([{"save": "d"}])"}}),
         "view atrium.json --size 32x18 --frames 1 --panel-script ps.json", 1,
         "step 0 saves d: is a directory", kXvfb},
        {"PanelSaveIntoAMissingFolder",
         with(kAtriumCopy, {{"ps.json", R"([{"save": "nowhere/s.json"}])"}}),
         "view atrium.json --size 32x18 --frames 1 --panel-script ps.json",
         1,
         "nowhere/s.json: cannot create a file in nowhere",
         kXvfb,
         true,
         {"nowhere"}},
        {"PanelSaveOntoTheReportLog",
         with(kAtriumCopy, {{"ps.json", R"([{"save": "log.json"}])"}}),
         "view atrium.json --size 32x18 --frames 1 --report-log log.json --panel-script ps.json",
         1,
         "step 0 saves log.json: is the same file as --report-log",
         kXvfb,
         true,
         {"log.json"}},
        // A user's own NAME.part is not the save's temporary.
        {"PanelSaveLeavesTheUsersPartFile",
         with(kAtriumCopy, {{"s.json.part", "mine"}, {"ps.json", R"([{"save": "s.json"}])"}}),
         "view atrium.json --size 32x18 --frames 1 --panel-script ps.json", 0, "", kXvfb, false},

        // 42: bench counts a scene's cookies among what it reads, and its outputs cannot collide.
        {"BenchCookieIsTheCsv",
         with(cookieScene("res/bench.csv"),
              {{"b.json", R"({"frames": 1, "warmup": 0, "size": "16x16", "measureError": false,
                            "scenes": ["{dir}/glass.json"], "profiles": ["balanced"]})"}}),
         "bench --config b.json --out res", 1,
         "--out res/bench.csv: is a file a scene of the benchmark reads"},
        {"BenchCookieIsAStrip",
         with(cookieScene("res/strips/glass_epipolar_balanced.png"),
              {{"b.json", R"({"frames": 1, "warmup": 0, "size": "16x16",
                            "scenes": ["{dir}/glass.json"], "profiles": ["balanced"]})"}}),
         "bench --config b.json --out res", 1,
         "--out res/strips/glass_epipolar_balanced.png: is a file a scene of the benchmark reads"},
        {"BenchLabelsOfOneStrip",
         {{"b.json", R"({"frames": 1, "warmup": 0, "size": "16x16", "scenes": ["{scene:atrium}"],
                        "methods": [], "configurations": [{"label": "a/b"}, {"label": "a_b"}]})"}},
         "bench --config b.json --out res",
         1,
         "runs 'a/b' on atrium and 'a_b' on atrium would write the same strip atrium_a_b.png",
         "",
         true,
         {"res"}},
        {"BenchSizeGivenTwice",
         {{"b.json", R"({"frames": 1, "warmup": 0, "size": "16x16", "scenes": ["{scene:atrium}"],
                        "methods": [], "configurations": [{"label": "x",
                        "sizes": ["32x18", "32x18"]}]})"}},
         "bench --config b.json --out res",
         1,
         "the run labelled 'x 32x18' comes twice on atrium",
         "",
         true,
         {"res"}},
        {"BenchLabelledLikeAProfileRun",
         {{"b.json", R"({"frames": 1, "warmup": 0, "size": "16x16", "scenes": ["{scene:atrium}"],
                        "methods": ["epipolar"], "profiles": ["balanced"],
                        "configurations": [{"label": "epipolar balanced"}]})"}},
         "bench --config b.json --out res",
         1,
         "the run labelled 'epipolar balanced' comes twice on atrium",
         "",
         true,
         {"res"}},
        {"BenchTwoScenesOfOneName",
         {{"a/scene.json", R"({"gltf": "{src}/scenes/atrium.gltf", "light": {"type": "point"}})"},
          {"b/scene.json", R"({"gltf": "{src}/scenes/atrium.gltf", "light": {"type": "point"}})"},
          {"b.json", R"({"frames": 1, "warmup": 0, "size": "16x16", "profiles": ["balanced"],
                        "scenes": ["{dir}/a/scene.json", "{dir}/b/scene.json"]})"}},
         "bench --config b.json --out res",
         1,
         "are both named 'scene'",
         "",
         true,
         {"res"}},

        // 42: a full disk (a file-size limit, with SIGXFSZ ignored so that writes fail with
        // EFBIG) is an error naming the file, and leaves nothing behind.
        {"RenderPngOnAFullDisk",
         {},
         "render {scene:atrium} --size 160x90 --out o.png",
         1,
         "--out o.png: cannot write the PNG: File too large",
         kFullDisk,
         true,
         {"o.png"}},
        {"RenderExrOnAFullDisk",
         {},
         "render {scene:atrium} --size 160x90 --out o.exr",
         1,
         "--out o.exr: cannot write the OpenEXR: File too large",
         kFullDisk,
         true,
         {"o.exr"}},
        {"PatternOnAFullDisk",
         {},
         "pattern --size 160x90 --out o.png",
         1,
         "--out o.png: cannot write the PNG: File too large",
         kFullDisk,
         true,
         {"o.png"}},
        {"ScreenshotOnAFullDisk",
         {},
         "view {scene:atrium} --size 160x90 --frames 1 --screenshot o.png",
         1,
         "--screenshot o.png: cannot write the PNG: File too large",
         kXvfb + " sh -c \"" + kFullDisk + " exec \\\"\\$0\\\" \\\"\\$@\\\"\"",
         true,
         {"o.png"}},
        {"BenchReferenceOnAFullDisk",
         {{"b.json", R"({"frames": 1, "warmup": 0, "size": "32x18", "scenes": ["{scene:atrium}"],
                        "profiles": ["balanced"]})"}},
         "bench --config b.json --out res",
         1,
         "cannot write the OpenEXR: File too large",
         kFullDisk,
         false},
    };
}

class CliHostile : public testing::TestWithParam<Row> {};

TEST_P(CliHostile, RefusesInOneLineAndTouchesNoInput) {
    const Row& row = GetParam();
    const fs::path dir = fs::path(cli_test::scratch()) / row.name;
    fs::create_directories(dir);
    std::map<fs::path, std::string> before;
    for (const auto& [name, text] : row.files) {
        const fs::path p = dir / name;
        fs::create_directories(p.parent_path());
        const std::string content = text.rfind("@copy:", 0) == 0
                                        ? readAll(fs::path(kSrc) / text.substr(6))
                                        : expanded(text, dir.string());
        std::ofstream(p, std::ios::binary) << content;
        before[p] = content;
    }
    const cli_test::Result r =
        cli_test::run(expanded(row.arguments), "cd '" + dir.string() + "' && " + row.prefix);
    if (row.exitCode != 0 && row.oneLine) {
        // One line, besides the device the command chose when it got that far.
        std::vector<std::string> lines;
        for (size_t at = 0, end; at < r.out.size(); at = end + 1) {
            end = std::min(r.out.find('\n', at), r.out.size());
            const std::string line = r.out.substr(at, end - at);
            if (line.rfind("lightscatter: using Vulkan device", 0) != 0) lines.push_back(line);
        }
        EXPECT_EQ(lines.size(), 1u) << r.out;
        EXPECT_EQ(r.out.find("lightscatter: lightscatter:"), std::string::npos) << r.out;
    }
    EXPECT_EQ(r.exitCode, row.exitCode) << r.out.substr(0, 2000);
    EXPECT_NE(r.out.find(row.words), std::string::npos) << r.out.substr(0, 2000);
    if (!row.wrong.empty()) {
        EXPECT_EQ(r.out.find(row.wrong), std::string::npos) << r.out;
    }
    if (row.maxChars) {
        EXPECT_LE(r.out.size(), row.maxChars) << r.out.substr(0, 2000);
    }
    for (const auto& [p, content] : before)
        EXPECT_TRUE(readAll(p) == content) << p << " was changed";
    for (const auto& e : fs::recursive_directory_iterator(dir))
        EXPECT_EQ(e.path().string().find(".partial"), std::string::npos) << e.path();
}

INSTANTIATE_TEST_SUITE_P(Table, CliHostile, testing::ValuesIn(rows()),
                         [](const testing::TestParamInfo<Row>& row) {
                             return std::string(row.param.name);
                         });

}  // namespace
