// Epipolar's step counter (DebugOptions::countSteps): off by default and absent from the report;
// on, plausible counts, and the min/max trees measurably cut the shadow-map look-ups on a scene
// whose rays are mostly lit, while the image stays what the march without trees gives.
#include <algorithm>
#include <cstdio>

#include "plugin_fixture.h"

using namespace plugin_test;
using lightscatter::Method;

namespace {

// The grille under `light` at 128x72 with a 512^2 shadow map: each ray crosses up to a few hundred
// texels, mostly lit, between the bars' shadows.
FrameSpec longLitRuns(lightscatter::Light light) {
    light.shadowMapSize = 512;
    return sceneWith(light, {128, 72});
}

lightscatter::Settings countingSettings(VkExtent2D screen, bool trees) {
    auto s = smallSettings(screen);
    s.shadowMapSize = 512;
    s.epipolar.minMaxTrees = trees;
    return s;
}

}  // namespace

class StepCountsGpu : public PluginGpuTest {
  protected:
    lightscatter::FrameReport render(TestFrame& frame, const lightscatter::Settings& settings,
                                     bool count, std::vector<float>* lin = nullptr) {
        frame.resetColor();
        auto d = frame.description(Method::Epipolar, lightscatter::Profile::Custom, settings);
        d.debug.countSteps = count;
        const auto r = plugin().render(d);
        if (lin) *lin = frame.inscatter();
        return r;
    }
};

TEST_F(StepCountsGpu, OffByDefaultNothingIsCounted) {
    ASSERT_FALSE(lightscatter::DebugOptions{}.countSteps);
    TestFrame frame(dev(), sceneWith(spotOverGrille()));
    const auto r = render(frame, smallSettings(frame.spec().screen), false);
    EXPECT_TRUE(r.timed);
    EXPECT_FALSE(r.steps.has_value());
    EXPECT_FALSE(ranPass(r, "clear step counts"));
}

TEST_F(StepCountsGpu, CountsArePlausible) {
    TestFrame frame(dev(), longLitRuns(spotOverGrille()));
    for (bool trees : {false, true}) {
        const auto r = render(frame, countingSettings(frame.spec().screen, trees), true);
        ASSERT_TRUE(r.steps.has_value()) << "trees " << trees;
        const lightscatter::StepCounts& s = *r.steps;
        EXPECT_TRUE(ranPass(r, "clear step counts"));
        EXPECT_GT(s.samples, 0u);
        EXPECT_GT(s.rays, 0u);
        EXPECT_LE(s.rays, s.samples);
        EXPECT_LE(s.degenerateRays, s.rays);
        EXPECT_GT(s.lineSteps, s.rays);  // a ray through the map crosses more than one texel
        if (trees) {
            EXPECT_GT(s.treeNodes, 0u);
        } else {
            EXPECT_EQ(s.treeNodes, 0u);
        }
        // The counter is cleared each frame: a second frame counts the same.
        const auto again = render(frame, countingSettings(frame.spec().screen, trees), true);
        ASSERT_TRUE(again.steps.has_value());
        EXPECT_EQ(again.steps->lineSteps, s.lineSteps);
        EXPECT_EQ(again.steps->samples, s.samples);
    }
}

// Issue #14: the trees decide something. Without them every ray visits every texel it crosses.
// The spot's shadow map is built with a near plane of 0.5 m, and of 1 cm as the host example's are
// (its depth then crowds against 1, where a tree stored in float16 as depth itself kept bounds a
// metre or more apart and decided almost nothing), and the sun's is orthographic.
TEST_F(StepCountsGpu, TreesCutTheShadowMapLookUpsOnLongLitRuns) {
    struct Case {
        const char* name;
        lightscatter::Light light;
        float shadowNear;
    };
    for (const Case& c : {Case{"spot", spotOverGrille(), 0.5f},
                          Case{"spot, near plane 1 cm", spotOverGrille(), 0.01f},
                          Case{"sun", sunThroughGrille(), 0.5f}}) {
        const char* name = c.name;
        FrameSpec spec = longLitRuns(c.light);
        spec.shadowNear = c.shadowNear;
        TestFrame frame(dev(), spec);
        std::vector<float> withTrees, without;
        const auto a = render(frame, countingSettings(frame.spec().screen, true), true, &withTrees);
        const auto b = render(frame, countingSettings(frame.spec().screen, false), true, &without);
        ASSERT_TRUE(a.steps && b.steps) << name;
        const lightscatter::StepCounts &t = *a.steps, &n = *b.steps;
        // The same samples and rays are marched either way; only the walk along the line differs.
        EXPECT_EQ(t.samples, n.samples) << name;
        EXPECT_EQ(t.rays, n.rays) << name;
        EXPECT_EQ(t.degenerateRays, n.degenerateRays) << name;
        const double lookUpRatio = static_cast<double>(n.lineSteps) /
                                   static_cast<double>(std::max<uint64_t>(t.lineSteps, 1));
        const double workRatio =
            static_cast<double>(n.lineSteps) /
            static_cast<double>(std::max<uint64_t>(t.lineSteps + t.treeNodes, 1));
        std::printf(
            "%s: %llu samples, %llu rays; look-ups without trees %llu, with %llu (+ %llu nodes): "
            "%.1fx fewer look-ups, %.1fx less work\n",
            name, static_cast<unsigned long long>(t.samples),
            static_cast<unsigned long long>(t.rays), static_cast<unsigned long long>(n.lineSteps),
            static_cast<unsigned long long>(t.lineSteps),
            static_cast<unsigned long long>(t.treeNodes), lookUpRatio, workRatio);
        EXPECT_GT(lookUpRatio, 20.0) << name;
        EXPECT_GT(workRatio, 6.0) << name;
        // ... and decide exactly as visiting every texel would
        // (MinMaxTreesOnAndOffGiveTheSameImage).
        const ErrorStats e = compare(withTrees, without);
        EXPECT_GT(e.peak, 0.0) << name;
        EXPECT_LT(e.maxRelative, 1e-3) << name;
    }
}

// Each slice's tree is built from the camera's point on its line on (min_max_trees.comp): every ray
// of the slice enters the map at or past it, so no node before it is ever tested. A sun whose
// map holds the camera (about half of each line before it), a spot whose cone holds the camera,
// and one the camera is behind (its lines come from infinity: nothing skipped). Trees started
// eight samples past the camera's point (ten later than they start) fail the sun's and the first
// spot's.
TEST_F(StepCountsGpu, NoRayTestsATreeNodeTheTreesSkipped) {
    // Above and behind the camera (0, 2.5, 9), which its cone holds; and in front of the camera,
    // facing away from it.
    lightscatter::Light over = spotOverGrille();
    over.position = {0.0f, 6.0f, 12.0f};
    over.direction = {0.0f, -0.4f, -1.0f};
    over.innerConeAngleDegrees = over.outerConeAngleDegrees = 35.0f;
    lightscatter::Light below = spotOverGrille();
    below.position = {0.3f, 2.0f, 6.5f};
    below.direction = {0.0f, -0.2f, -1.0f};
    struct Case {
        const char* name;
        lightscatter::Light light;
    };
    for (const Case& c : {Case{"sun", sunThroughGrille()}, Case{"spot over the camera", over},
                          Case{"spot the camera is behind", below}}) {
        TestFrame frame(dev(), longLitRuns(c.light));
        const auto r = render(frame, countingSettings(frame.spec().screen, true), true);
        ASSERT_TRUE(r.steps.has_value()) << c.name;
        EXPECT_GT(r.steps->treeNodes, 1000u) << c.name;
        EXPECT_EQ(r.steps->unbuiltTreeNodes, 0u) << c.name;
    }
}

// A frame of several lights counts every light's march: two spots together count what each does
// alone, field by field.
TEST_F(StepCountsGpu, AFrameOfTwoLightsCountsBothMarches) {
    lightscatter::Light second = spotOverGrille();
    second.position = {-1.5f, 5.0f, 0.8f};
    second.direction = {0.25f, -1.0f, -0.1f};
    TestFrame a(dev(), sceneWith(spotOverGrille()));
    TestFrame b(dev(), sceneWith(second));
    const auto settings = smallSettings(a.spec().screen);
    auto da = a.description(Method::Epipolar, lightscatter::Profile::Custom, settings);
    auto db = b.description(Method::Epipolar, lightscatter::Profile::Custom, settings);
    da.debug.countSteps = db.debug.countSteps = true;
    const auto ra = plugin().render(da);
    const auto rb = plugin().render(db);
    auto both = da;
    both.lights = {{da.light, da.shadowMap, da.lightColor},
                   {db.light, db.shadowMap, db.lightColor}};
    both.light = {};
    both.shadowMap.reset();
    both.lightColor.reset();
    const auto r = plugin().render(both);
    ASSERT_TRUE(ra.steps && rb.steps && r.steps);
    EXPECT_GT(ra.steps->rays, 0u);
    EXPECT_GT(rb.steps->rays, 0u);
    EXPECT_EQ(r.steps->samples, ra.steps->samples + rb.steps->samples);
    EXPECT_EQ(r.steps->rays, ra.steps->rays + rb.steps->rays);
    EXPECT_EQ(r.steps->lineSteps, ra.steps->lineSteps + rb.steps->lineSteps);
    EXPECT_EQ(r.steps->treeNodes, ra.steps->treeNodes + rb.steps->treeNodes);
    EXPECT_EQ(r.steps->degenerateRays, ra.steps->degenerateRays + rb.steps->degenerateRays);
    EXPECT_EQ(r.steps->degenerateSteps, ra.steps->degenerateSteps + rb.steps->degenerateSteps);
}
