// A scene far from the world's origin renders as it does at the origin (issue #42: planes gave a
// shaft 54% low at 1e7 m and 22% high at 1e6 m, where brute force and epipolar held). The light's
// volume is placed on the CPU in double precision and the planes are rasterised and shaded from
// the camera (frame constants' viewProjFromCamera), not through a world-space matrix whose
// translation cancels in float. Each method is held to the float64 reference of the scene as its
// floats place it.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "bench/metrics.h"
#include "engine_renderer.h"
#include "exact_renderer/reference_renderer.h"
#include "scene/scene.h"
#include "support/gpu_test.h"

namespace {

class FarFromOrigin : public testing_support::GpuTest {};

// The spot of light_center, unshadowed and without its models: nothing but the light, the medium
// and the camera, so that only the method's own arithmetic moves with the offset.
host::SceneDesc spotAt(const glm::vec3& offset) {
    host::SceneDesc s =
        host::loadSceneFile(std::string(LS_SOURCE_DIR) + "/scenes/hard/light_center.json");
    s.models.clear();
    s.light.shadowMapSize = 0;
    s.camera.position += offset;
    s.camera.target += offset;
    s.light.position += offset;
    return s;
}

TEST_F(FarFromOrigin, AMillionMetresOutEachMethodIsAsGoodAsAtTheOrigin) {
    const VkExtent2D size{64, 36};
    const host::MeshData noMesh;
    const lightscatter::Method methods[] = {
        lightscatter::Method::Planes, lightscatter::Method::BeamTreeSampling,
        lightscatter::Method::BruteForce, lightscatter::Method::Epipolar};
    std::map<lightscatter::Method, double> atHome;
    for (float distance : {0.0f, 1e6f, 1e7f}) {
        // The float64 reference of the scene as its floats place it there.
        const host::SceneDesc scene = spotAt(glm::vec3(distance, 0.0f, 0.5f * distance));
        const auto reference =
            host::reference::renderReference(scene, noMesh, size.width, size.height);
        host::EngineRenderer renderer(dev(), scene, noMesh, size);
        for (lightscatter::Method method : methods) {
            host::RenderOptions options;
            options.method = method;
            const auto e = host::bench::compareToReference(renderer.render(options).inscatter,
                                                           reference.rgb, scene.exposure);
            std::printf("%-20s %.0e m: %.4f\n", lightscatter::methodName(method), distance,
                        e.meanRelative);
            EXPECT_EQ(e.nonFinite, 0u);
            if (distance == 0.0f) atHome[method] = e.meanRelative;
            // At 1e6 m each method within 2% of its error at the origin (measured: planes 0.080
            // against 0.082, beam-tree-sampling 0.021 against 0.0095, brute force and epipolar
            // 0.0048 against 0.0004; before, planes 0.134 and beam-tree-sampling 0.065). At 1e7 m
            // the engine's float view matrix itself places the camera to within a metre only,
            // and every method, brute force included, is 64-137% off this 5-metre scene: a limit
            // of the input (docs/integration.md: rebase a world that large on the camera).
            if (distance == 1e6f) {
                EXPECT_LT(e.meanRelative, atHome[method] + 0.02)
                    << lightscatter::methodName(method);
            }
        }
    }
}

}  // namespace
