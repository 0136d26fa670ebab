// The 1000-box field (scenes/occluders_1000) with seed 004's two methods, small, under validation:
// its tree gives more triangles than the plugin's first triangle buffer holds (test_occluder_scenes
// checks that), the buffer grows to the frame's need, and nothing is dropped: Lin stays as close to
// brute force (the same shadow map, marched per pixel) as it does for the 10-box field. A dropped
// lit pyramid leaves an entry without its exit (or the reverse), which shows as a large error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bench/metrics.h"
#include "engine_renderer.h"
#include "support/gpu_test.h"

namespace {

// Lin of a beam-tree method against brute force's, and the tree's CPU time.
struct Result {
    double meanRelative = 0;
    size_t nonFinite = 0;
    double cpuMilliseconds = 0;
};

Result againstBruteForce(rg::Device& device, int count, lightscatter::Method method) {
    const VkExtent2D size{64, 36};
    const host::SceneDesc scene = host::loadSceneFile(
        std::string(LS_SOURCE_DIR) + "/scenes/occluders_" + std::to_string(count) + ".json");
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    host::EngineRenderer renderer(device, scene, mesh, size);
    EXPECT_EQ(renderer.occluderCount(), static_cast<size_t>(count) + 1);
    host::RenderOptions options;
    options.method = lightscatter::Method::BruteForce;
    const host::FrameOutput brute = renderer.render(options);
    options.method = method;
    const host::FrameOutput tree = renderer.render(options);
    EXPECT_EQ(tree.plugin.method, lightscatter::methodName(method));
    Result r;
    if (tree.plugin.cpuWork.size() == 1) r.cpuMilliseconds = tree.plugin.cpuWork[0].milliseconds;
    EXPECT_EQ(tree.plugin.cpuWork.size(), 1u);
    std::vector<double> reference(brute.inscatter.size() / 4 * 3);
    for (size_t p = 0; p < reference.size() / 3; ++p)
        for (size_t c = 0; c < 3; ++c) reference[p * 3 + c] = brute.inscatter[p * 4 + c];
    const auto e = host::bench::compareToReference(tree.inscatter, reference, scene.exposure);
    r.meanRelative = e.meanRelative;
    r.nonFinite = e.nonFinite;
    std::printf("occluders_%d: %s against brute force %.4f, tree %.1f ms on the CPU\n", count,
                lightscatter::methodName(method), e.meanRelative, r.cpuMilliseconds);
    return r;
}

}  // namespace

class OccludersGpu : public testing_support::GpuTest {};

TEST_F(OccludersGpu, AThousandBoxFrameDropsNoTriangles) {
    for (lightscatter::Method method :
         {lightscatter::Method::BeamTreeAnalytic, lightscatter::Method::BeamTreeSampling}) {
        const Result few = againstBruteForce(dev(), 10, method);
        const Result many = againstBruteForce(dev(), 1000, method);
        EXPECT_EQ(few.nonFinite, 0u);
        EXPECT_EQ(many.nonFinite, 0u);
        // Measured on lavapipe, beam-tree-analytic: 0.0004 (10 boxes) and 0.0008 (1000 boxes);
        // beam-tree-sampling, whose planes sample the lit space too: 0.0073 and 0.012. With the
        // buffer left at its first size (triangles dropped) the 1000-box frames measured 0.99 and
        // 0.98 (and the 10-box sampling frame 0.20).
        const double bound = method == lightscatter::Method::BeamTreeAnalytic ? 0.005 : 0.03;
        EXPECT_LT(few.meanRelative, bound) << lightscatter::methodName(method);
        EXPECT_LT(many.meanRelative, bound) << lightscatter::methodName(method);
    }
}
