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

#include <cmath>

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

// The cube map's seams: a view ray that passes from one face's frustum into another's (the major
// axis of P - light changes along it) is marched through both faces' layers. Those rays must be as
// close to the reference as the rays that stay in one face, and within the spot cases' bound.
TEST_F(PointCageGpu, RaysAcrossCubeFacesMatchTheReferenceLikeTheOthers) {
    const host::SceneDesc scene = cageScene();
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    const auto reference = host::reference::renderReference(scene, mesh, kSize.width, kSize.height);
    const host::reference::ReferenceScene rays(scene, mesh, kSize.width, kSize.height);
    host::EngineRenderer renderer(dev(), scene, mesh, kSize);
    host::RenderOptions options;
    options.method = lightscatter::Method::BruteForce;
    const host::FrameOutput out = renderer.render(options);

    const glm::dvec3 light = rays.light().position;
    auto face = [&](const glm::dvec3& p) {
        const glm::dvec3 d = p - light, a = glm::abs(d);
        const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
        return 2 * axis + (d[axis] < 0.0 ? 1 : 0);
    };
    double errorAcross = 0, refAcross = 0, errorWithin = 0, refWithin = 0;
    size_t across = 0, within = 0;
    for (uint32_t y = 0; y < kSize.height; ++y)
        for (uint32_t x = 0; x < kSize.width; ++x) {
            const ls::ref::Ray r = rays.pixelRay(x, y);
            bool crosses = false;
            const int first = face(r.origin + r.direction * (r.length * 0.5 / 512.0));
            for (int k = 1; k < 512 && !crosses; ++k)
                crosses = face(r.origin + r.direction * (r.length * (k + 0.5) / 512.0)) != first;
            const size_t i = size_t{y} * kSize.width + x;
            double e = 0, v = 0;
            for (size_t c = 0; c < 3; ++c) {
                e += std::fabs(out.inscatter[i * 4 + c] - reference.rgb[i * 3 + c]);
                v += std::fabs(reference.rgb[i * 3 + c]);
            }
            (crosses ? errorAcross : errorWithin) += e;
            (crosses ? refAcross : refWithin) += v;
            ++(crosses ? across : within);
        }
    const double acrossError = errorAcross / refAcross, withinError = errorWithin / refWithin;
    std::printf(
        "point_cage %ux%u, brute-force: %zu rays cross cube faces (mean relative error "
        "%.4f), %zu stay in one (%.4f)\n",
        kSize.width, kSize.height, across, acrossError, within, withinError);
    ASSERT_GT(across, kSize.width * kSize.height / 4);
    ASSERT_GT(within, 20u);
    EXPECT_LT(acrossError, 0.045);
    EXPECT_LT(acrossError, 2.0 * withinError + 0.005);
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
