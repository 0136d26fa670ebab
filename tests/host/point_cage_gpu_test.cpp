// A shadowed point light (scenes/point_cage: a light in a cage of bars, shafts in every direction)
// through its cube shadow map: epipolar (every face in each pass) and brute force against the
// float64 reference renderer, which traces the same bars exactly, small and under validation;
// cone-march, planes and the beam trees through the face each of their points lies in. Analytic
// refuses it.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "bench/metrics.h"
#include "engine_renderer.h"
#include "exact_renderer/reference_renderer.h"
#include "support/gpu_test.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace {

const VkExtent2D kSize{64, 36};

// Measured on lavapipe at kSize (docs/methods.md), with room for driver differences: cone-march
// 0.232 (32 samples per pixel miss thin shafts near the light, as on point_at_camera), planes
// 0.162 (128 planes, as on the hard cases), beam-tree-sampling 0.062 (its planes near the light
// thinner and in closed form; 0.163 with seed 002's planes alone), beam-tree-analytic 0.009.
// Without the cube map: cone-march 0.540, planes 0.567, beam-tree-analytic 0.020 (the beam trees
// keep the bars' shadows from their occluder boxes).
constexpr double kConeMarchBound = 0.3, kPlanesBound = 0.2, kBeamTreeAnalyticBound = 0.015,
                 kBeamTreeSamplingBound = 0.09;

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

TEST_F(PointCageGpu, EpipolarAndBruteForceMatchTheReference) {
    const host::SceneDesc scene = cageScene();
    ASSERT_EQ(scene.light.type, lightscatter::LightType::Point);
    ASSERT_GT(scene.light.shadowMapSize, 0u);
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    const auto reference = host::reference::renderReference(scene, mesh, kSize.width, kSize.height);

    host::EngineRenderer renderer(dev(), scene, mesh, kSize);
    host::RenderOptions options;
    options.method = lightscatter::Method::BruteForce;
    const host::FrameOutput brute = renderer.render(options);
    EXPECT_EQ(brute.plugin.method, "brute-force");
    const double bruteError = againstReference(brute, reference.rgb, scene.exposure, "brute-force");
    options.method = lightscatter::Method::Epipolar;
    const host::FrameOutput epipolar = renderer.render(options);
    EXPECT_EQ(epipolar.plugin.method, "epipolar");
    const double epipolarError =
        againstReference(epipolar, reference.rgb, scene.exposure, "epipolar");

    // The same light without its cube map: the shafts are gone, and the bounds see it.
    host::SceneDesc open = scene;
    open.light.shadowMapSize = 0;
    host::EngineRenderer unshadowedRenderer(dev(), open, mesh, kSize);
    const host::FrameOutput unshadowed = unshadowedRenderer.render(options);
    const double unshadowedError =
        againstReference(unshadowed, reference.rgb, scene.exposure, "unshadowed");

    // Measured on lavapipe (see docs/methods.md); the spot hard cases' bounds are 0.01-0.045 for
    // brute-force and 0.03-0.22 for epipolar.
    EXPECT_LT(bruteError, 0.045);
    EXPECT_LT(epipolarError, 0.09);
    EXPECT_GT(unshadowedError, 2.0 * 0.09);
}

// The cube map's seams: a view ray that passes from one face's frustum into another's (the major
// axis of P - light changes along it) is marched through both faces' layers (brute force), or in
// parts by both faces' passes (epipolar). Those rays must be as close to the reference as the rays
// that stay in one face, and within the spot cases' bound.
TEST_F(PointCageGpu, RaysAcrossCubeFacesMatchTheReferenceLikeTheOthers) {
    const host::SceneDesc scene = cageScene();
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    const auto reference = host::reference::renderReference(scene, mesh, kSize.width, kSize.height);
    const host::reference::ReferenceScene rays(scene, mesh, kSize.width, kSize.height);
    host::EngineRenderer renderer(dev(), scene, mesh, kSize);

    const glm::dvec3 light = rays.light().position;
    auto face = [&](const glm::dvec3& p) {
        const glm::dvec3 d = p - light, a = glm::abs(d);
        const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
        return 2 * axis + (d[axis] < 0.0 ? 1 : 0);
    };
    std::vector<bool> crossing(size_t{kSize.width} * kSize.height);
    for (uint32_t y = 0; y < kSize.height; ++y)
        for (uint32_t x = 0; x < kSize.width; ++x) {
            const ls::ref::Ray r = rays.pixelRay(x, y);
            bool crosses = false;
            const int first = face(r.origin + r.direction * (r.length * 0.5 / 512.0));
            for (int k = 1; k < 512 && !crosses; ++k)
                crosses = face(r.origin + r.direction * (r.length * (k + 0.5) / 512.0)) != first;
            crossing[size_t{y} * kSize.width + x] = crosses;
        }
    const size_t across = static_cast<size_t>(std::count(crossing.begin(), crossing.end(), true));
    ASSERT_GT(across, crossing.size() / 4);
    ASSERT_GT(crossing.size() - across, 20u);

    // The spot hard cases' bounds (hard_suite_test.cpp): brute-force 0.045, epipolar 0.09.
    for (const auto& [method, bound] : {std::pair{lightscatter::Method::BruteForce, 0.045},
                                        std::pair{lightscatter::Method::Epipolar, 0.09}}) {
        host::RenderOptions options;
        options.method = method;
        const host::FrameOutput out = renderer.render(options);
        double errorAcross = 0, refAcross = 0, errorWithin = 0, refWithin = 0;
        for (size_t i = 0; i < crossing.size(); ++i) {
            double e = 0, v = 0;
            for (size_t c = 0; c < 3; ++c) {
                e += std::fabs(out.inscatter[i * 4 + c] - reference.rgb[i * 3 + c]);
                v += std::fabs(reference.rgb[i * 3 + c]);
            }
            (crossing[i] ? errorAcross : errorWithin) += e;
            (crossing[i] ? refAcross : refWithin) += v;
        }
        const double acrossError = errorAcross / refAcross, withinError = errorWithin / refWithin;
        std::printf(
            "point_cage %ux%u, %s: %zu rays cross cube faces (mean relative error %.4f), %zu stay "
            "in "
            "one (%.4f)\n",
            kSize.width, kSize.height, lightscatter::methodName(method), across, acrossError,
            crossing.size() - across, withinError);
        EXPECT_LT(acrossError, bound) << lightscatter::methodName(method);
        EXPECT_LT(acrossError, 2.0 * withinError + 0.005) << lightscatter::methodName(method);
    }
}

// Looking away from the light along +Z with a narrow view, only the +Z face's pyramid reaches the
// view: the other faces' passes record nothing, and the frame is what brute force gives.
TEST_F(PointCageGpu, EpipolarMarchesOnlyTheFacesThatReachTheView) {
    host::SceneDesc scene = cageScene();
    scene.camera.position = {0.0f, 2.0f, 3.0f};
    scene.camera.target = {0.3f, 1.8f, 10.0f};
    scene.camera.fovYDegrees = 40.0f;
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    host::EngineRenderer renderer(dev(), scene, mesh, kSize);
    host::RenderOptions options;
    options.method = lightscatter::Method::BruteForce;
    const host::FrameOutput brute = renderer.render(options);
    options.method = lightscatter::Method::Epipolar;
    const host::FrameOutput epipolar = renderer.render(options);
    EXPECT_NE(epipolar.plugin.reason.find("cube faces reaching the view: +Z ("), std::string::npos)
        << epipolar.plugin.reason;
    double diff = 0, sum = 0;
    for (size_t i = 0; i < brute.inscatter.size(); ++i)
        if (i % 4 != 3) {
            diff += std::fabs(epipolar.inscatter[i] - brute.inscatter[i]);
            sum += std::fabs(brute.inscatter[i]);
        }
    std::printf("point_cage looking away along +Z: epipolar within %.4f of brute force\n",
                diff / sum);
    ASSERT_GT(sum, 0.0);
    EXPECT_LT(diff / sum, 0.05);

    // From the default camera, which sees the cage from outside, every face reaches the view.
    host::EngineRenderer outside(dev(), cageScene(), mesh, kSize);
    const host::FrameOutput all = outside.render(options);
    EXPECT_NE(all.plugin.reason.find("cube faces reaching the view: +X, -X, +Y, -Y, +Z, -Z"),
              std::string::npos)
        << all.plugin.reason;
}

// The samples near the light's screen position pass millimetres from it, where the coordinate
// texture's rounding (RG16: 1.5e-5 of the screen) turned their rays texels off the face's line; the
// march took them for degenerate and marched them texel by texel across the face (at 320x180,
// 322685 such steps against 728426 along the lines). Put back on their lines, they are marched
// along them: 2232 and 718976.
TEST_F(PointCageGpu, RaysNearTheLightAreMarchedAlongTheirLines) {
    const host::SceneDesc scene = cageScene();
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    host::EngineRenderer renderer(dev(), scene, mesh, {320, 180});
    host::RenderOptions options;
    options.method = lightscatter::Method::Epipolar;
    options.countSteps = true;
    const host::FrameOutput out = renderer.render(options);
    ASSERT_TRUE(out.plugin.steps.has_value());
    const lightscatter::StepCounts& s = *out.plugin.steps;
    std::printf(
        "point_cage 320x180: %llu degenerate rays, %llu texel steps of theirs, %llu steps "
        "along the lines\n",
        static_cast<unsigned long long>(s.degenerateRays),
        static_cast<unsigned long long>(s.degenerateSteps),
        static_cast<unsigned long long>(s.lineSteps));
    ASSERT_GT(s.lineSteps, 0u);
    EXPECT_LT(static_cast<double>(s.degenerateSteps), 0.02 * static_cast<double>(s.lineSteps));
    // Each face's trees start at the camera's point on the line where the camera is in front of
    // the face (min_max_trees.comp): no ray tests a node before it.
    EXPECT_GT(s.treeNodes, 0u);
    EXPECT_EQ(s.unbuiltTreeNodes, 0u);
}

TEST_F(PointCageGpu, AutoFollowsTheScreenAndAnalyticRefusesTheCubeMap) {
    const host::SceneDesc scene = cageScene();
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    host::RenderOptions options;
    options.method = lightscatter::Method::Auto;
    // Auto follows the screen, as for any shadowed light: per-pixel marching on a tiny one,
    // epipolar sampling where the samples are fewer than the pixels.
    host::EngineRenderer tiny(dev(), scene, mesh, {16, 16});
    const host::FrameOutput small = tiny.render(options);
    EXPECT_EQ(small.plugin.method, "brute-force");
    EXPECT_NE(small.plugin.reason.find("cube shadow map"), std::string::npos)
        << small.plugin.reason;
    options.profile = lightscatter::Profile::Custom;
    options.custom.epipolar.slices = 16;
    options.custom.epipolar.samplesPerSlice = 16;
    const host::FrameOutput larger = tiny.render(options);
    EXPECT_EQ(larger.plugin.method, "epipolar") << larger.plugin.reason;
    options.profile = lightscatter::Profile::Balanced;
    options.method = lightscatter::Method::Analytic;
    try {
        (void)tiny.render(options);
        ADD_FAILURE() << "analytic accepted a cube shadow map";
    } catch (const host::SceneError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("method analytic cannot sample a point light's cube shadow map"),
                  std::string::npos)
            << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

// Issue #25: the methods that sample a light at points (cone-march's samples, the planes, the beam
// trees' sampling planes in their uncertain space) look up the cube face each point lies in, and
// match the reference with bounds the same light without its cube map misses (0.18 and more).
TEST_F(PointCageGpu, EveryMethodThatSamplesPointsReadsTheCubeMap) {
    const host::SceneDesc scene = cageScene();
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    const auto reference = host::reference::renderReference(scene, mesh, kSize.width, kSize.height);
    host::EngineRenderer renderer(dev(), scene, mesh, kSize);
    host::SceneDesc open = scene;
    open.light.shadowMapSize = 0;
    host::EngineRenderer unshadowedRenderer(dev(), open, mesh, kSize);
    struct Bound {
        lightscatter::Method method;
        double bound;
        bool mapDecides;  // the same light without its cube map misses the bound
    };
    // beam-tree-sampling's uncertain space, where it reads the map, is small in this scene (the
    // boxes' shadows decide most of it): its bound holds its planes' error, and the cube map's use
    // is the other three methods' (the same planes shader).
    for (const Bound& b :
         {Bound{lightscatter::Method::ConeMarch, kConeMarchBound, true},
          Bound{lightscatter::Method::Planes, kPlanesBound, true},
          Bound{lightscatter::Method::BeamTreeAnalytic, kBeamTreeAnalyticBound, true},
          Bound{lightscatter::Method::BeamTreeSampling, kBeamTreeSamplingBound, false}}) {
        host::RenderOptions options;
        options.method = b.method;
        const host::FrameOutput out = renderer.render(options);
        EXPECT_EQ(out.plugin.method, lightscatter::methodName(b.method));
        const double error = againstReference(out, reference.rgb, scene.exposure,
                                              lightscatter::methodName(b.method));
        EXPECT_LT(error, b.bound) << lightscatter::methodName(b.method);
        if (!b.mapDecides) continue;
        const host::FrameOutput unshadowed = unshadowedRenderer.render(options);
        const std::string what = std::string(lightscatter::methodName(b.method)) + ", unshadowed";
        EXPECT_GT(againstReference(unshadowed, reference.rgb, scene.exposure, what.c_str()),
                  b.bound)
            << what;
    }
}

// The hard case point_in_cage (scenes/hard): the light on screen in a small cage, seen through a
// gap with a bar right behind it. Every slice's first sample lies on the light's screen position,
// and its ray passes through the light: into one texel of each face, so one shadow-map look-up
// decided each face's part of it, and behind the light that look-up fell on the bar, the surface
// the ray ends on and the map holds, with half the light's glow on that part (docs/epipolar.md, "A
// point light's cube map", "Near the light's screen position"). The four pixels nearest the
// light interpolate from that sample: measured 0.289 off the reference before, 0.0075 after. At
// 160x90 the frame is then within 1.5x of brute force's error (measured 1.33x; 1.98x before).
TEST_F(PointCageGpu, EpipolarMatchesTheReferenceAtTheLightsScreenPosition) {
    const host::SceneDesc scene =
        host::loadSceneFile(std::string(LS_SOURCE_DIR) + "/scenes/hard/point_in_cage.json");
    ASSERT_GT(scene.light.shadowMapSize, 0u);
    const VkExtent2D size{160, 90};
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    const auto reference = host::reference::renderReference(scene, mesh, size.width, size.height);
    const host::reference::ReferenceScene rays(scene, mesh, size.width, size.height);

    // The four pixels whose rays pass nearest the light.
    const glm::dvec3 light = rays.light().position;
    std::vector<std::pair<double, size_t>> nearest;
    for (uint32_t y = 0; y < size.height; ++y)
        for (uint32_t x = 0; x < size.width; ++x) {
            const ls::ref::Ray r = rays.pixelRay(x, y);
            nearest.emplace_back(glm::length(glm::cross(light - r.origin, r.direction)),
                                 size_t{y} * size.width + x);
        }
    std::partial_sort(nearest.begin(), nearest.begin() + 4, nearest.end());
    nearest.resize(4);

    host::EngineRenderer renderer(dev(), scene, mesh, size);
    host::RenderOptions options;
    options.method = lightscatter::Method::BruteForce;
    const host::FrameOutput brute = renderer.render(options);
    options.method = lightscatter::Method::Epipolar;
    const host::FrameOutput epipolar = renderer.render(options);
    EXPECT_EQ(epipolar.plugin.method, "epipolar");

    double error = 0, sum = 0;
    for (const auto& [distance, i] : nearest)
        for (size_t c = 0; c < 3; ++c) {
            error += std::fabs(epipolar.inscatter[i * 4 + c] - reference.rgb[i * 3 + c]);
            sum += std::fabs(reference.rgb[i * 3 + c]);
        }
    const double bruteError =
        host::bench::compareToReference(brute.inscatter, reference.rgb, scene.exposure)
            .meanRelative;
    const double epipolarError =
        host::bench::compareToReference(epipolar.inscatter, reference.rgb, scene.exposure)
            .meanRelative;
    std::printf(
        "point_in_cage %ux%u: the 4 pixels nearest the light %.4f off the reference (epipolar); "
        "the "
        "frame %.4f (epipolar), %.4f (brute force)\n",
        size.width, size.height, error / sum, epipolarError, bruteError);
    ASSERT_GT(sum, 0.0);
    EXPECT_LT(error / sum, 0.03);
    EXPECT_LT(epipolarError, 1.5 * bruteError);
}
