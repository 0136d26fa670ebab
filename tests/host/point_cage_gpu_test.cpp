// A shadowed point light (scenes/point_cage: a light in a cage of bars, shafts in every direction)
// through its cube shadow map: brute force against the float64 reference renderer, which traces
// the same bars exactly, small and under validation. The other methods refuse the cube map in one
// line and auto picks brute force.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "bench/metrics.h"
#include "engine_renderer.h"
#include "exact_renderer/reference_renderer.h"
#include "support/gpu_test.h"

namespace {

const VkExtent2D kSize{64, 36};

host::SceneDesc cageScene() {
    return host::loadSceneFile(std::string(LS_SOURCE_DIR) + "/scenes/point_cage.json");
}

double againstReference(const host::FrameOutput& out, const std::vector<double>& reference,
                        float exposure, const char* what) {
    const auto e = host::bench::compareToReference(out.inscatter, reference, exposure);
    EXPECT_EQ(e.nonFinite, 0u) << what;
    std::printf("point_cage %ux%u, %s: mean relative error %.4f against the float64 reference\n",
                kSize.width, kSize.height, what, e.meanRelative);
    return e.meanRelative;
}

}  // namespace

class PointCageGpu : public testing_support::GpuTest {};

TEST_F(PointCageGpu, BruteForceMatchesTheReference) {
    const host::SceneDesc scene = cageScene();
    ASSERT_EQ(scene.light.type, host::LightKind::Point);
    ASSERT_GT(scene.light.shadowMapSize, 0u);
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    const auto reference = host::reference::renderReference(scene, mesh, kSize.width, kSize.height);

    host::EngineRenderer renderer(dev(), scene, mesh, kSize);
    host::RenderOptions options;
    options.method = lightscatter::Method::BruteForce;
    const host::FrameOutput brute = renderer.render(options);
    EXPECT_EQ(brute.plugin.method, "brute-force");
    const double error = againstReference(brute, reference.rgb, scene.exposure, "brute-force");

    // The same light without its cube map: the shafts are gone, and the bound sees it.
    host::SceneDesc open = scene;
    open.light.shadowMapSize = 0;
    host::EngineRenderer unshadowedRenderer(dev(), open, mesh, kSize);
    const host::FrameOutput unshadowed = unshadowedRenderer.render(options);
    const double unshadowedError =
        againstReference(unshadowed, reference.rgb, scene.exposure, "unshadowed");

    // Measured on lavapipe (see docs/methods.md); the spot hard cases' brute-force bounds are
    // 0.01-0.045.
    EXPECT_LT(error, 0.045);
    EXPECT_GT(unshadowedError, 2.0 * 0.045);
}

TEST_F(PointCageGpu, OnlyBruteForceSamplesTheCubeMap) {
    const host::SceneDesc scene = cageScene();
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    host::EngineRenderer renderer(dev(), scene, mesh, {16, 16});
    host::RenderOptions options;
    options.method = lightscatter::Method::Auto;
    const host::FrameOutput chosen = renderer.render(options);
    EXPECT_EQ(chosen.plugin.method, "brute-force");
    EXPECT_NE(chosen.plugin.reason.find("cube shadow map"), std::string::npos)
        << chosen.plugin.reason;
    for (lightscatter::Method m :
         {lightscatter::Method::Epipolar, lightscatter::Method::Analytic,
          lightscatter::Method::ConeMarch, lightscatter::Method::Slices,
          lightscatter::Method::BeamTreeAnalytic, lightscatter::Method::BeamTreeSampling}) {
        options.method = m;
        try {
            (void)renderer.render(options);
            ADD_FAILURE() << lightscatter::methodName(m) << " accepted a cube shadow map";
        } catch (const host::SceneError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(std::string("method ") + lightscatter::methodName(m) +
                                " cannot sample a point light's cube shadow map"),
                      std::string::npos)
                << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
}
