// The hard-case suite (scenes/hard, made by tools/make_hard_cases.py): every case, every method, at
// 64x36 with the balanced profile, against the float64 reference with exact visibility. Each must
// give finite pixels and stay within the bound docs/performance.md states for it (mean relative
// error of Lin, sum |a - b| / sum |b|); thin media within 1% of float64.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "bench/metrics.h"
#include "engine_renderer.h"
#include "exact_renderer/reference_renderer.h"
#include "support/gpu_test.h"

namespace {

struct Bound {
    double epipolar, bruteForce;
};

// Measured on lavapipe (see docs/performance.md), with room for driver differences. Where the
// epipolar bound is loose the error is interpolation along too few samples of a 64-pixel line
// (an initial step of 16); brute force's is the shadow map's.
const std::map<std::string, Bound> kBounds = {
    {"spot_at_camera", {0.22, 0.045}},         {"point_at_camera", {0.045, 0.045}},
    {"sun_into_view", {0.09, 0.036}},          {"dense_medium", {0.08, 0.015}},
    {"reversed_z", {0.09, 0.015}},             {"reversed_infinite", {0.09, 0.015}},
    {"zero_extinction_channel", {0.09, 0.015}}, {"shadow_map_not_pow2", {0.10, 0.017}},
    {"light_center", {0.03, 0.01}},            {"thin_medium_km", {0.01, 0.01}},
};
constexpr Bound kDefault{0.02, 0.01};

}  // namespace

class HardSuite : public testing_support::GpuTest {};

TEST_F(HardSuite, EveryCaseIsFiniteAndWithinItsBound) {
    const VkExtent2D size{64, 36};
    size_t cases = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(LS_SOURCE_DIR) + "/scenes/hard")) {
        if (entry.path().extension() != ".json") continue;
        const std::string name = entry.path().stem().string();
        const host::SceneDesc scene = host::loadSceneFile(entry.path().string());
        const host::MeshData mesh = host::loadSceneMeshes(scene);
        const auto reference = host::reference::renderReference(scene, mesh, size.width, size.height);
        host::EngineRenderer renderer(dev(), scene, mesh, size);
        const Bound bound = kBounds.count(name) ? kBounds.at(name) : kDefault;
        for (lightscatter::Method method : {lightscatter::Method::Epipolar, lightscatter::Method::BruteForce}) {
            host::RenderOptions options;
            options.method = method;
            const host::FrameOutput out = renderer.render(options);
            const auto e = host::bench::compareToReference(out.inscatter, reference.rgb, scene.exposure);
            for (float v : out.color) ASSERT_TRUE(std::isfinite(v)) << name;
            EXPECT_EQ(e.nonFinite, 0u) << name;
            const double limit = method == lightscatter::Method::Epipolar ? bound.epipolar : bound.bruteForce;
            EXPECT_LE(e.meanRelative, limit) << name << " (" << lightscatter::methodName(method) << ")";
        }
        ++cases;
    }
    EXPECT_GE(cases, 20u);
}
