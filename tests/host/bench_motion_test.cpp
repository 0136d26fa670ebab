// The benchmark's temporal-stability mode without a device: the flicker measure on images whose
// answer is known, the motions' poses, the reference cache's key, and the configuration's rules
// for "motion" (each bad value one line naming the file and the field).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "bench/bench_config.h"
#include "bench/flicker.h"
#include "bench/motion.h"
#include "bench/reference_cache.h"

namespace {

using host::bench::FlickerMeter;
using host::bench::FlickerMetrics;

constexpr size_t kPixels = 64 * 36;

// A reference whose values vary from pixel to pixel (1 to 2), shifted by `frame` pixels, so that
// consecutive frames differ.
std::vector<double> reference(int frame) {
    std::vector<double> r(kPixels * 3);
    for (size_t p = 0; p < kPixels; ++p)
        for (size_t c = 0; c < 3; ++c)
            r[p * 3 + c] =
                1.5 + 0.5 * std::sin(0.1 * static_cast<double>(p + size_t(frame)) + double(c));
    return r;
}

std::vector<float> asMethod(const std::vector<double>& rgb, double scale = 1.0) {
    std::vector<float> rgba(kPixels * 4, 1.0f);
    for (size_t p = 0; p < kPixels; ++p)
        for (size_t c = 0; c < 3; ++c) rgba[p * 4 + c] = static_cast<float>(scale * rgb[p * 3 + c]);
    return rgba;
}

// Values stored as float, as the cache and the GPU do, so that "equal" below is exact.
std::vector<double> rounded(std::vector<double> rgb) {
    for (double& v : rgb) v = static_cast<float>(v);
    return rgb;
}

TEST(Flicker, AStillSceneRenderedTheSameEveryFrameHasNone) {
    FlickerMeter meter;
    const std::vector<double> ref = reference(0);
    const std::vector<float> method = asMethod(ref, 1.05);  // 5% off, the same every frame
    for (int k = 0; k < 6; ++k) meter.add(method, ref);
    const FlickerMetrics f = meter.result();
    EXPECT_EQ(f.framePairs, 5u);
    EXPECT_EQ(f.meanExcess, 0.0);
    EXPECT_EQ(f.p99Excess, 0.0);
    EXPECT_EQ(f.maxExcess, 0.0);
    EXPECT_EQ(f.meanErrorChange, 0.0);
    EXPECT_EQ(f.referenceChange, 0.0);
    EXPECT_NEAR(f.meanRelativeError, 0.05, 1e-6);
}

TEST(Flicker, AMethodThatFollowsTheMotionExactlyHasNone) {
    FlickerMeter meter;
    for (int k = 0; k < 6; ++k) {
        const std::vector<double> ref = rounded(reference(k));
        meter.add(asMethod(ref), ref);
    }
    const FlickerMetrics f = meter.result();
    EXPECT_GT(f.referenceChange, 0.01);
    EXPECT_EQ(f.methodChange, f.referenceChange);
    EXPECT_EQ(f.meanExcess, 0.0);
    EXPECT_EQ(f.meanErrorChange, 0.0);
    EXPECT_EQ(f.meanRelativeError, 0.0);
}

TEST(Flicker, InjectedNoiseIsMeasuredAtItsExpectedSize) {
    // L_k = R (1 + a u_k), u uniform in [-1, 1] and new every frame and pixel, R still: the excess
    // is a R |u_k - u_{k-1}|, whose mean over R is a E|u - u'| = 2a/3, and whose 99th percentile
    // (R = 1 here) solves (1 - x/2)^2 = 0.01: x = 1.8a.
    const double a = 0.02;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> ref(kPixels * 3, 1.0);
    FlickerMeter meter;
    for (int k = 0; k < 20; ++k) {
        std::vector<float> method(kPixels * 4, 1.0f);
        for (size_t p = 0; p < kPixels; ++p)
            for (size_t c = 0; c < 3; ++c) method[p * 4 + c] = static_cast<float>(1.0 + a * u(rng));
        meter.add(method, ref);
    }
    const FlickerMetrics f = meter.result();
    EXPECT_NEAR(f.meanExcess, 2.0 * a / 3.0, 0.02 * a);
    EXPECT_NEAR(f.p99Excess, 1.8 * a, 0.05 * a);
    EXPECT_NEAR(f.meanErrorChange, f.meanExcess, 1e-9);  // nothing moves: the two agree
    EXPECT_EQ(f.referenceChange, 0.0);
    EXPECT_NEAR(f.meanRelativeError, a / 2.0, 0.02 * a);  // E|a u| = a/2
    // The heat map holds the same mean per pixel.
    double sum = 0;
    for (double v : meter.excessMap()) sum += v;
    EXPECT_NEAR(sum / kPixels, 2.0 * a / 3.0, 0.02 * a);
}

TEST(Flicker, ABiasThatMovesWithTheShaftsIsNotFlickerButItsErrorChanges) {
    // 10% too bright everywhere: the method changes 1.1 times as much as the reference, so the
    // excess is a tenth of the reference's change; the error changes by the same amount.
    FlickerMeter meter;
    for (int k = 0; k < 6; ++k) {
        const std::vector<double> ref = reference(k);
        meter.add(asMethod(ref, 1.1), ref);
    }
    const FlickerMetrics f = meter.result();
    EXPECT_NEAR(f.meanExcess, 0.1 * f.referenceChange, 1e-6);
    EXPECT_NEAR(f.meanErrorChange, 0.1 * f.referenceChange, 1e-6);

    // A method that does not move at all has no excess (it changes less than the reference), but
    // its error changes exactly as the reference does: the second measure sees what the first
    // does not.
    FlickerMeter frozen;
    const std::vector<float> still = asMethod(reference(0));
    for (int k = 0; k < 6; ++k) frozen.add(still, reference(k));
    const FlickerMetrics g = frozen.result();
    EXPECT_EQ(g.meanExcess, 0.0);
    EXPECT_NEAR(g.meanErrorChange, g.referenceChange, 1e-6);
}

TEST(Flicker, NonFiniteValuesAreCountedNotAveraged) {
    FlickerMeter meter;
    const std::vector<double> ref = reference(0);
    std::vector<float> method = asMethod(ref);
    meter.add(method, ref);
    method[5 * 4 + 1] = NAN;
    meter.add(method, ref);
    meter.add(asMethod(ref), ref);
    const FlickerMetrics f = meter.result();
    EXPECT_EQ(f.nonFinite, 1u);
    EXPECT_EQ(f.meanExcess, 0.0);
    EXPECT_TRUE(std::isfinite(f.meanErrorChange));
}

TEST(Flicker, ImagesOfDifferentSizesAreRefused) {
    FlickerMeter meter;
    const std::vector<double> ref = reference(0);
    EXPECT_THROW(meter.add(std::vector<float>(8, 0.0f), ref), std::logic_error);
    meter.add(asMethod(ref), ref);
    EXPECT_THROW(meter.add(std::vector<float>(8, 0.0f), std::vector<double>(6, 0.0)),
                 std::logic_error);
}

host::SceneDesc scene(const char* name) {
    return host::loadSceneFile(std::string(LS_SOURCE_DIR) + "/scenes/" + name + ".json");
}

double degreesBetween(glm::vec3 a, glm::vec3 b) {
    return glm::degrees(std::acos(
        std::clamp(double(glm::dot(glm::normalize(glm::dvec3(a)), glm::normalize(glm::dvec3(b)))),
                   -1.0, 1.0)));
}

TEST(Motion, TheCameraMovesRightAndTurnsRightBySteps) {
    const host::SceneDesc start = scene("atrium");
    host::bench::Motion m;
    m.cameraMetresPerFrame = 0.05;
    m.cameraDegreesPerFrame = 0.2;
    const auto& c0 = start.camera;
    const glm::vec3 right = glm::normalize(glm::cross(c0.target - c0.position, c0.up));
    const host::SceneDesc p0 = host::bench::poseAt(start, host::bench::MotionKind::Camera, m, 0);
    EXPECT_EQ(p0.camera.position, c0.position);
    EXPECT_EQ(p0.light.direction, start.light.direction);
    const host::SceneDesc p10 = host::bench::poseAt(start, host::bench::MotionKind::Camera, m, 10);
    EXPECT_NEAR(glm::length(p10.camera.position - c0.position), 0.5, 1e-5);
    EXPECT_NEAR(glm::dot(p10.camera.position - c0.position, right), 0.5, 1e-5);
    // The turn is about up: 2 degrees between the view directions as seen from above.
    const glm::vec3 up = glm::normalize(c0.up);
    auto flat = [&](glm::vec3 v) { return v - glm::dot(v, up) * up; };
    const glm::vec3 f0 = c0.target - c0.position, f10 = p10.camera.target - p10.camera.position;
    EXPECT_NEAR(degreesBetween(flat(f0), flat(f10)), 2.0, 1e-3);
    EXPECT_GT(glm::dot(glm::normalize(f10), right), 0.0f) << "turned left";
    EXPECT_EQ(p10.light.direction, start.light.direction) << "the light stays";
}

TEST(Motion, ASunTurnsTowardsTheCamerasRightAndASpotMoves) {
    host::bench::Motion m;
    const host::SceneDesc sun = scene("atrium");
    ASSERT_EQ(sun.light.type, lightscatter::LightType::Directional);
    const auto& c = sun.camera;
    const glm::vec3 right = glm::normalize(glm::cross(c.target - c.position, c.up));
    const host::SceneDesc s30 = host::bench::poseAt(sun, host::bench::MotionKind::Light, m, 30);
    EXPECT_NEAR(degreesBetween(sun.light.direction, s30.light.direction), 3.0, 1e-3);
    EXPECT_GT(glm::dot(s30.light.direction - sun.light.direction, right), 0.0f);
    EXPECT_EQ(s30.camera.position, c.position) << "the camera stays";

    const host::SceneDesc spot = scene("window_room");
    ASSERT_EQ(spot.light.type, lightscatter::LightType::Spot);
    const host::SceneDesc p30 = host::bench::poseAt(spot, host::bench::MotionKind::Light, m, 30);
    EXPECT_NEAR(glm::length(p30.light.position - spot.light.position), 0.6, 1e-5);
    EXPECT_EQ(p30.light.direction, spot.light.direction);
}

// The still pass judges a method that keeps history on the frames after its warm-up: every frame
// is the scene's own pose, its camera and its light alike.
TEST(Motion, StillKeepsTheScenesPose) {
    host::bench::Motion m;
    for (const char* name : {"atrium", "window_room"}) {
        const host::SceneDesc start = scene(name);
        const host::SceneDesc p = host::bench::poseAt(start, host::bench::MotionKind::Still, m, 30);
        EXPECT_EQ(p.camera.position, start.camera.position) << name;
        EXPECT_EQ(p.camera.target, start.camera.target) << name;
        EXPECT_EQ(p.light.position, start.light.position) << name;
        EXPECT_EQ(p.light.direction, start.light.direction) << name;
    }
    EXPECT_STREQ(host::bench::motionName(host::bench::MotionKind::Still), "still");
}

TEST(ReferenceCache, TheKeyChangesWithWhatTheReferenceDependsOn) {
    const host::SceneDesc s = scene("window_room");
    host::MeshData mesh;
    mesh.vertices.resize(3);
    mesh.vertices[1].position = {1, 0, 0};
    mesh.vertices[2].position = {0, 1, 0};
    mesh.indices = {0, 1, 2};
    const VkExtent2D size{160, 90};
    const std::string key = host::bench::referenceKey(s, mesh, size);
    EXPECT_EQ(key, host::bench::referenceKey(s, mesh, size)) << "not deterministic";
    EXPECT_NE(key, host::bench::referenceKey(s, mesh, {240, 135}));
    host::bench::Motion m;
    EXPECT_NE(key, host::bench::referenceKey(
                       host::bench::poseAt(s, host::bench::MotionKind::Light, m, 1), mesh, size));
    EXPECT_NE(key, host::bench::referenceKey(
                       host::bench::poseAt(s, host::bench::MotionKind::Camera, m, 1), mesh, size));
    host::SceneDesc fog = s;
    fog.medium.betaM *= 2.0f;
    EXPECT_NE(key, host::bench::referenceKey(fog, mesh, size));
    host::MeshData moved = mesh;
    moved.vertices[2].position.z = 1e-3f;
    EXPECT_NE(key, host::bench::referenceKey(s, moved, size));
    // The shadow map is the GPU's; the reference traces the triangles.
    host::SceneDesc smaller = s;
    smaller.light.shadowMapSize = 512;
    EXPECT_EQ(key, host::bench::referenceKey(smaller, mesh, size));
}

// A configuration file in a folder of its own (per process: ctest runs these tests side by side,
// and a shared file was read half-written); loadBenchConfig's message for it.
std::string configError(const std::string& text) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("ls_bench_motion_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto file = dir / "motion.json";
    std::ofstream(file) << text;
    try {
        (void)host::bench::loadBenchConfig(file.string(), LS_SOURCE_DIR);
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        const std::string prefix = file.string() + ": ";
        EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
        return what.substr(prefix.size());
    }
    return "(accepted)";
}

std::string withMotion(const std::string& motion) {
    return R"({"size": "32x18", "scenes": ["scenes/atrium.json"], "motion": )" + motion + "}";
}

TEST(BenchConfigMotion, EachBadValueIsOneLineNamingTheField) {
    EXPECT_EQ(configError(withMotion("3")),
              "motion must be an object (keys: what, frames, lightDegreesPerFrame, "
              "lightMetresPerFrame, cameraMetresPerFrame, cameraDegreesPerFrame)");
    EXPECT_EQ(configError(withMotion(R"({"what": "light", "speed": 2})")),
              "motion: unknown key 'speed' (known: what, frames, lightDegreesPerFrame, "
              "lightMetresPerFrame, cameraMetresPerFrame, cameraDegreesPerFrame)");
    EXPECT_EQ(configError(withMotion(R"({"frames": 60})")),
              "motion.what is required: \"light\", \"camera\", \"still\" or an array of them");
    EXPECT_EQ(configError(withMotion(R"({"what": []})")),
              "motion.what = []: must be \"light\", \"camera\", \"still\" or a non-empty array of "
              "them");
    EXPECT_EQ(configError(withMotion(R"({"what": "sun"})")),
              "motion.what[] = \"sun\": must be \"light\", \"camera\" or \"still\"");
    EXPECT_EQ(configError(withMotion(R"({"what": ["light", "light"]})")),
              "motion.what lists \"light\" twice");
    EXPECT_EQ(configError(withMotion(R"({"what": "light", "frames": 1})")),
              "motion.frames = 1: must be a whole number from 2 to 10000");
    EXPECT_EQ(configError(withMotion(R"({"what": "light", "frames": 4294967298})")),
              "motion.frames = 4294967298: must be a whole number from 2 to 10000");
    EXPECT_EQ(configError(withMotion(R"({"what": "light", "lightDegreesPerFrame": -0.1})")),
              "motion.lightDegreesPerFrame = -0.1: must be a number from 0 to 10");
    EXPECT_EQ(configError(withMotion(R"({"what": "camera", "cameraMetresPerFrame": "0.1"})")),
              "motion.cameraMetresPerFrame = \"0.1\": must be a number from 0 to 10");
    EXPECT_EQ(configError(withMotion(R"({"what": "camera", "cameraDegreesPerFrame": 11})")),
              "motion.cameraDegreesPerFrame = 11: must be a number from 0 to 10");
    EXPECT_EQ(configError(withMotion(R"({"what": "light", "lightMetresPerFrame": null})")),
              "motion.lightMetresPerFrame = null: must be a number from 0 to 10");
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"], "measureError": false,
                              "motion": {"what": "light"}})"),
              "motion needs measureError: the flicker is measured against the float64 reference "
              "at every pose");
}

TEST(BenchConfigMotion, TheRefinementThresholdSweepFollowsThePluginsRule) {
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"],
                              "sweeps": {"refinementThreshold": [0.01, 0]}})"),
              "sweeps.refinementThreshold (run 'refinementThreshold=0'): "
              "epipolar.refinementThreshold = 0: must be > 0 and finite (only compared)");
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"],
                              "sweeps": {"refinementThreshold": ["small"]}})"),
              "sweeps.refinementThreshold[] = \"small\": must be a number");
}

// A float field is compared with the floats nearest its bounds (issue #42): a sweep or a
// configuration at a bound as its table writes it runs; past it, the message quotes the bound.
TEST(BenchConfigMotion, FieldsAreAcceptedAtTheirBounds) {
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"],
                              "sweeps": {"froxelHistoryWeight": [0.99], "planeRange": [1e30],
                                         "planeSpacing": [1e-6]}})"),
              "(accepted)");
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"], "configurations": [{"label": "w",
                              "method": "froxels", "froxels": {"historyWeight": 0.99,
                              "farDistance": 1e-6}}]})"),
              "(accepted)");
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"],
                              "sweeps": {"froxelHistoryWeight": [0.9900001]}})"),
              "sweeps.froxelHistoryWeight (run 'froxelHistoryWeight=0.9900001'): "
              "froxels.historyWeight = 0.9900001: must be in [0, 0.99] (the history's share of "
              "each froxel; 1 would never take a new frame)");
}

TEST(BenchConfigMotion, DefaultsAndEveryMotion) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("ls_bench_motion_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto file = dir / "good.json";
    std::ofstream(file) << withMotion(
        R"({"what": ["camera", "light", "still"], "lightMetresPerFrame": 0})");
    const host::bench::BenchConfig c = host::bench::loadBenchConfig(file.string(), LS_SOURCE_DIR);
    ASSERT_TRUE(c.motion);
    ASSERT_EQ(c.motion->what.size(), 3u);
    EXPECT_EQ(c.motion->what[0], host::bench::MotionKind::Camera);
    EXPECT_EQ(c.motion->what[1], host::bench::MotionKind::Light);
    EXPECT_EQ(c.motion->what[2], host::bench::MotionKind::Still);
    EXPECT_EQ(c.motion->frames, 60);
    EXPECT_EQ(c.motion->lightMetresPerFrame, 0.0);
    EXPECT_EQ(c.motion->lightDegreesPerFrame, 0.1);

    std::ofstream(file) << R"({"scenes": ["scenes/atrium.json"]})";
    EXPECT_FALSE(host::bench::loadBenchConfig(file.string(), LS_SOURCE_DIR).motion);
}

}  // namespace

namespace {

std::string deepArray(size_t levels) {
    return std::string(levels, '[') + std::string(levels, ']');
}

// A deep value in any of these keys used to overflow the stack (exit 139, no message): in an error
// message that wrote it out, or in a copy of it. The parser refuses it now, naming the field.
TEST(BenchConfigInput, DeepNestingIsRefusedInEveryKey) {
    const std::string scenes = R"("scenes": ["scenes/atrium.json"])";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"frames", "{" + scenes + R"(, "frames": %})"},
        {"measureError", "{" + scenes + R"(, "measureError": %})"},
        {"size", "{" + scenes + R"(, "size": %})"},
        {"scenes", R"({"scenes": %})"},
        {"sweeps.slices", "{" + scenes + R"(, "sweeps": {"slices": %}})"},
        {"sweeps.planes.target", "{" + scenes + R"(, "sweeps": {"planes.target": %}})"},
        {"configurations[0].coneMarch.samples",
         "{" + scenes + R"(, "configurations": [{"label": "a", "coneMarch": {"samples": %}}]})"},
    };
    for (size_t levels : {size_t{30000}, size_t{100000}}) {
        for (const auto& [field, text] : cases) {
            SCOPED_TRACE(field + " " + std::to_string(levels));
            std::string file = text;
            file.replace(file.find('%'), 1, deepArray(levels));
            const std::string m = configError(file);
            EXPECT_EQ(m.rfind(field + "[0][0][0]", 0), 0u) << m;
            EXPECT_NE(m.find(": arrays and objects nest more than 64 deep here"), std::string::npos)
                << m;
            EXPECT_LE(m.size(), 200u) << m;
        }
    }
}

// Runs grow as scenes x sweep values, the square of the file: a 30 KB file made a million runs
// (hundreds of MB, a minute of checks). Refused at 10,000, 24 times the largest shipped one. The
// runs are distinct (the noise's amplitude in steps of 1e-4): two alike are refused on their own.
TEST(BenchConfigInput, AConfigurationOfTooManyRunsIsRefused) {
    // One epipolar balanced run and `runs` - 1 of the amplitude's sweep.
    auto config = [](int runs) {
        std::string values;
        for (int i = 0; i + 1 < runs; ++i)
            values += std::string(i ? "," : "") + std::to_string(i) + "e-4";
        return R"({"methods": ["epipolar"], "scenes": ["scenes/atrium.json"], "sweeps": )"
               R"({"noiseAmplitude": [)" +
               values + "]}}";
    };
    EXPECT_EQ(configError(config(10001)),
              "expands to more than 10000 runs (scenes x methods, profiles and sweep values): "
              "split it into several configurations");
    EXPECT_EQ(configError(config(10000)), "(accepted)");
}

// parseSize quotes its text as it is: a "\n" in a configuration's size made a two-line error
// (found by bench_fuzzer; tests/fuzz/corpus/bench/size-newline).
TEST(BenchConfigInput, ASizeIsEchoedOnOneLine) {
    EXPECT_EQ(
        configError(R"({"scenes": ["scenes/atrium.json"], "sweeps": {"size": ["\n960x540"]}})"),
        "sweeps.size[] '\\n960x540' is not WIDTHxHEIGHT with both whole numbers from 1 to "
        "16384");
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"], "size": "64x"})"),
              "size '64x' is not WIDTHxHEIGHT with both whole numbers from 1 to 16384");
}

TEST(BenchConfigInput, RepeatedKeysAndLongValues) {
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"], "frames": 2, "frames": 3})"),
              "key 'frames' appears twice in one object");
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"],
                              "sweeps": {"slices": [64], "slices": [128]}})"),
              "sweeps: key 'slices' appears twice in one object");
    std::string many = R"({"scenes": ["scenes/atrium.json"], "sweeps": {"planes.target": [)";
    for (int i = 0; i < 100000; ++i) many += "[1],";
    const std::string m = configError(many + "[1]]}}");
    EXPECT_EQ(m, "sweeps.planes.target[] = [1]: must be one of float16, float32, rgba8");
    const std::string size = configError(R"({"scenes": ["scenes/atrium.json"], "size": ")" +
                                         std::string(100000, '9') + "\"}");
    EXPECT_EQ(size.rfind("size '9999", 0), 0u) << size;
    EXPECT_LE(size.size(), 200u) << size;
    const std::string scene = configError(R"({"scenes": [")" + std::string(100000, 's') + "\"]}");
    EXPECT_EQ(scene.rfind("scenes[0] = \"ssss", 0), 0u) << scene;
    EXPECT_LE(scene.size(), 200u) << scene;
    const std::string method = configError(R"({"scenes": ["scenes/atrium.json"], "methods": [")" +
                                           std::string(100000, 'm') + "\"]}");
    EXPECT_EQ(method.rfind("methods: unknown method 'mmmm", 0), 0u) << method;
    EXPECT_LE(method.size(), 400u) << method;  // the known methods follow
}

// "slices", the planes method's former name, in the method lists, and the planes' fields under
// their former flat names (slicePlanes, sliceTarget, sliceDither) in sweeps and configurations
// expand to the runs their current names do (a sweep's label and family are its key as the file
// gave it); a field under two of its names is refused, naming both.
TEST(BenchConfigInput, FormerNamesOfThePlanesMethodAndItsFields) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("ls_bench_motion_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto file = dir / "planes.json";
    auto runs = [&](const std::string& text) {
        std::ofstream(file) << text;
        std::vector<std::string> out;
        for (const auto& r : host::bench::loadBenchConfig(file.string(), LS_SOURCE_DIR).runs)
            out.push_back(r.label + " / " + r.family + " / " + lightscatter::methodName(r.method) +
                          " / " + std::to_string(r.settings.planes.count) + " " +
                          (r.settings.planes.target == lightscatter::PlaneTarget::Rgba8Channels
                               ? (r.settings.planes.dither ? "rgba8-dither" : "rgba8")
                               : "float"));
        return out;
    };
    // A scene's own method list, and the configuration's.
    const auto former = runs(R"({"scenes": ["scenes/atrium.json", {"scene":
        "scenes/window_room.json", "methods": ["slices"]}], "methods": ["epipolar", "slices"],
        "sweeps": {"slicePlanes": [64]}, "configurations": [{"label": "8-bit", "method": "slices",
        "slicePlanes": 64, "sliceTarget": "rgba8", "sliceDither": false}]})");
    const auto current = runs(R"({"scenes": ["scenes/atrium.json", {"scene":
        "scenes/window_room.json", "methods": ["planes"]}], "methods": ["epipolar", "planes"],
        "sweeps": {"planes.count": [64]}, "configurations": [{"label": "8-bit", "method": "planes",
        "planes": {"count": 64, "target": "rgba8", "dither": false}}]})");
    auto expected = [](const std::string& key) {
        const std::vector<std::string> planes{
            "planes / profiles / planes / 128 float",
            key + "=64 / " + key + " / planes / 64 float",
            "8-bit / configurations / planes / 64 rgba8",
        };
        std::vector<std::string> all{"epipolar balanced / profiles / epipolar / 128 float"};
        all.insert(all.end(), planes.begin(), planes.end());  // atrium
        all.insert(all.end(), planes.begin(), planes.end());  // window_room
        return all;
    };
    EXPECT_EQ(former, expected("slicePlanes"));
    EXPECT_EQ(current, expected("planes.count"));
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"],
                              "sweeps": {"planeCount": [64], "slicePlanes": [128]}})"),
              "sweeps.slicePlanes sweeps planes.count a second time (under another of its names): "
              "give it once");
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"], "configurations": [{"label": "a",
                              "planeCount": 64, "planes": {"count": 128}}]})"),
              "configurations[0].planes.count sets planes.count a second time (as planeCount): "
              "give it once");
    // The messages name the key as the file gave it.
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"], "sweeps": {"slicePlanes": [1]}})"),
              "sweeps.slicePlanes (run 'slicePlanes=1'): planes.count = 1: must be in [2, 4096]");
    EXPECT_EQ(configError(R"({"scenes": ["scenes/atrium.json"], "sweeps": {"sliceTarget":
                              ["rgba16"]}})"),
              "sweeps.sliceTarget[] = \"rgba16\": must be one of float16, float32, rgba8");
}

// The benchmark's own keys for settings are gone (#37): the compound sweeps (coneModes,
// planeTargets and its former name sliceTargets), samples and initialStep, and the configurations'
// samples, initialStep and coneMode are unknown keys, named in the refusal; planeTarget is
// planes.target's former name, which takes the field's values (rgba8-dither is rgba8 with
// planes.dither).
TEST(BenchConfigInput, TheBenchmarksOwnSettingsKeysAreGone) {
    const std::string scenes = R"({"scenes": ["scenes/atrium.json"], )";
    for (const std::string key :
         {"coneModes", "planeTargets", "sliceTargets", "samples", "initialStep"}) {
        const std::string m = configError(scenes + R"("sweeps": {")" + key + R"(": [1]}})");
        EXPECT_EQ(m.rfind("sweeps: unknown key '" + key +
                              "' (known: shadowMapSize, size, and every settings field: ",
                          0),
                  0u)
            << m;
    }
    for (const std::string key : {"samples", "initialStep", "coneMode"}) {
        const std::string m =
            configError(scenes + R"("configurations": [{"label": "a", ")" + key + R"(": 1}]})");
        EXPECT_EQ(m.rfind("configurations[0]: unknown key '" + key +
                              "' (known: label, method, from, sizes, shadowMapSize, family, and "
                              "every settings field: ",
                          0),
                  0u)
            << m;
    }
    EXPECT_EQ(configError(scenes + R"("configurations": [{"label": "a", "method": "planes",
                                      "planeTarget": "rgba8-dither"}]})"),
              "configurations[0].planeTarget = \"rgba8-dither\": must be one of float16, float32, "
              "rgba8");
    EXPECT_EQ(configError(scenes + R"("sweeps": {"planeTarget": ["rgba8", "rgba8-dither"]}})"),
              "sweeps.planeTarget[] = \"rgba8-dither\": must be one of float16, float32, rgba8");
}

}  // namespace
