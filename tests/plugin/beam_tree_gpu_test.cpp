// Seed 004's hybrid (beam-tree-analytic) on the GPU: without occluders the lit pyramids are the
// whole light volume and the closed form must match the unshadowed model; with the camera inside
// the cone looking at the light too, and for a point light whose backplate lies past the far plane.
#include <cmath>
#include <cstdio>

#include "model_conversion.h"
#include "plugin_fixture.h"

using namespace plugin_test;
using lightscatter::Method;

class BeamTreeGpu : public PluginGpuTest {};

TEST_F(BeamTreeGpu, WithoutOccludersTheLitVolumeIsTheUnshadowedModel) {
    struct Case {
        const char* what;
        FrameSpec spec;
    };
    std::vector<Case> cases;
    cases.push_back({"spot seen from outside its cone", flatSpot()});
    {
        FrameSpec s;
        s.screen = {48, 32};
        s.view = lookAt({0.0f, 1.0f, 6.0f}, {0.0f, 1.0f, -1.0f}, 60.0f, 1.5f, 0.05f, 200.0f);
        s.light = spotOverGrille();
        s.light.position = {0.0f, 1.2f, -4.0f};
        s.light.direction = {0.0f, 0.0f, 1.0f};  // at the camera, which is inside its cone
        s.light.range = 30.0f;
        s.medium = fog();
        s.shadowed = false;
        cases.push_back({"camera inside the cone, facing the light", s});
    }
    {
        // The backplate cube lies past the far plane (50 m): the lit pass must not clip it there.
        FrameSpec s = flatSpot();
        s.light.type = lightscatter::LightType::Point;
        s.light.position = {0.5f, 2.0f, 1.0f};
        cases.push_back({"point light in view, its backplate past the far plane", s});
    }
    for (const Case& c : cases) {
        TestFrame frame(dev(), c.spec);
        const auto report = run(frame, Method::BeamTreeAnalytic);
        EXPECT_EQ(report.method, "beam-tree-analytic");
        const ErrorStats e = compare(frame.inscatter(), float64Unshadowed(frame));
        std::printf("%s: mean error %.2e of the peak, max %.2e\n", c.what, e.meanRelative,
                    e.maxRelative);
        EXPECT_EQ(e.nonFinite, 0u);
        EXPECT_LT(e.meanRelative, 1e-3) << c.what;
    }
}

// One occluder, a plate over the ground under the spot, given as a thin outer box: pixels whose
// rays never pass behind the box (seen from the light) are fully lit, and there the closed form
// over the lit pyramids matches the float64 model to 1e-3 of the peak, and the frame without the
// box to 1e-4 of each pixel (the point table's own per-pixel error is 3e-3). Elsewhere the planes
// sample the shadow map.
TEST_F(BeamTreeGpu, OneBoxOccluderMatchesTheFloat64ModelInFullyLitRegions) {
    FrameSpec spec;
    spec.screen = {48, 32};
    spec.view = defaultView(spec.screen);
    spec.light = spotOverGrille();
    spec.medium = fog();
    Scene plate;
    plate.quads.push_back({{0.3, 3.0, 0.2}, {0.6, 0, 0}, {0, 0, -0.6}});
    spec.scene = plate;
    spec.scene.quads.push_back(
        {{0, 0, 0}, {20, 0, 0}, {0, 0, -20}});  // the ground, under everything
    TestFrame frame(dev(), spec);
    auto desc = frame.description(Method::BeamTreeAnalytic, lightscatter::Profile::Custom,
                                  smallSettings(spec.screen));
    lightscatter::Occluder o;
    o.outer.center = {0.3f, 3.0f, 0.2f};
    o.outer.halfExtents = {0.61f, 0.01f, 0.61f};
    desc.occluders = {o};
    const auto report = plugin().render(desc);
    EXPECT_EQ(report.method, "beam-tree-analytic");
    ASSERT_EQ(report.cpuWork.size(), 1u);
    std::printf("beam tree on the CPU: %.3f ms\n", report.cpuWork[0].milliseconds);
    const std::vector<float> got = frame.inscatter();
    const std::vector<float> unshadowed = float64Unshadowed(frame);
    desc.occluders.clear();  // the same frame with nothing in the way: the closed form's own error
    frame.resetColor();
    plugin().render(desc);
    const std::vector<float> open = frame.inscatter();
    double worstOpen = 0, worstAgainstOpen = 0, worstOfPeak = 0, peak = 0;
    for (size_t i = 0; i < unshadowed.size(); ++i)
        if (i % 4 != 3) peak = std::max(peak, static_cast<double>(unshadowed[i]));

    const auto light = refLight(frame.light());
    size_t lit = 0, shadowedRays = 0;
    double worst = 0;
    for (uint32_t y = 0; y < spec.screen.height; ++y)
        for (uint32_t x = 0; x < spec.screen.width; ++x) {
            const PixelRay r = pixelRay(spec.scene, spec.view, spec.screen.width,
                                        spec.screen.height, x, y, spec.medium.maxDistance);
            bool touchesShadow = false;
            for (int k = 0; k < 2000 && !touchesShadow; ++k) {
                const glm::dvec3 p = r.origin + r.dir * (r.S * (k + 0.5) / 2000.0);
                // Behind the occluder's box as the light sees it: the segment to the light meets
                // the box (slab test), which is what the tree knows (not the plate inside it).
                const glm::dvec3 lo(-0.31, 2.99, -0.41), hi(0.91, 3.01, 0.81);
                const glm::dvec3 d = light.position - p;
                double t0 = 0.0, t1 = 1.0;
                for (int a = 0; a < 3; ++a) {
                    if (std::fabs(d[a]) < 1e-12) {
                        if (p[a] < lo[a] || p[a] > hi[a]) t1 = -1.0;
                        continue;
                    }
                    double u = (lo[a] - p[a]) / d[a], v = (hi[a] - p[a]) / d[a];
                    if (u > v) std::swap(u, v);
                    t0 = std::max(t0, u);
                    t1 = std::min(t1, v);
                }
                touchesShadow = t0 <= t1;
            }
            if (touchesShadow) {
                ++shadowedRays;
                continue;
            }
            const size_t i = (size_t{y} * spec.screen.width + x) * 4;
            for (int c = 0; c < 3; ++c) {
                const double want = unshadowed[i + static_cast<size_t>(c)];
                if (want < 1e-6) continue;
                worst = std::max(worst, std::fabs(got[i + static_cast<size_t>(c)] - want) / want);
                const double g = got[i + static_cast<size_t>(c)],
                             without = open[i + static_cast<size_t>(c)];
                worstOpen = std::max(worstOpen, std::fabs(without - want) / want);
                worstAgainstOpen = std::max(worstAgainstOpen, std::fabs(g - without) / without);
                worstOfPeak = std::max(worstOfPeak, std::fabs(g - want) / peak);
            }
            ++lit;
        }
    std::printf(
        "one box: %zu fully lit pixels: worst error %.2e of the peak; per pixel %.2e, the same as "
        "the closed "
        "form's own without the box (%.2e), and %.2e from it; %zu rays pass behind the box\n",
        lit, worstOfPeak, worst, worstOpen, worstAgainstOpen, shadowedRays);
    EXPECT_GT(lit, 200u);
    EXPECT_GT(shadowedRays, 50u);
    EXPECT_LT(worstOfPeak, 1e-3);       // against float64
    EXPECT_LT(worstAgainstOpen, 1e-4);  // the tree adds nothing where all is lit
}
