// Several lights in one frame (FrameDescription::lights): the summed Lin of two lights equals the
// sum of the two single-light renders, for epipolar and brute force, each light on its own settings
// when it has them; a light whose volume misses the view adds no node; the refusals name the
// fields.
#include <algorithm>
#include <cmath>
#include <string>

#include "plugin_fixture.h"

using namespace plugin_test;
using lightscatter::Method;

namespace {

lightscatter::Light secondSpot() {
    lightscatter::Light l = spotOverGrille();
    l.position = {-1.5f, 5.0f, 0.8f};
    l.direction = {0.25f, -1.0f, -0.1f};
    l.intensity = {15.0f, 25.0f, 40.0f};
    l.innerConeAngleDegrees = l.outerConeAngleDegrees = 22.0f;
    return l;
}

lightscatter::LightInput input(const lightscatter::FrameDescription& d) {
    return {d.light, d.shadowMap, d.lightColor};
}

// `d` with its single light replaced by `lights`.
lightscatter::FrameDescription withLights(lightscatter::FrameDescription d,
                                          std::vector<lightscatter::LightInput> lights) {
    d.lights = std::move(lights);
    d.light = {};
    d.shadowMap.reset();
    d.lightColor.reset();
    return d;
}

double peakOf(const std::vector<float>& v) {
    double peak = 0;
    for (size_t i = 0; i < v.size(); ++i)
        if (i % 4 != 3) peak = std::max(peak, static_cast<double>(v[i]));
    return peak;
}

std::string refusal(const lightscatter::FrameDescription& d) {
    try {
        plugin().render(d);
    } catch (const lightscatter::InvalidInput& e) {
        return e.what();
    }
    return "(accepted)";
}

}  // namespace

class LightsGpu : public PluginGpuTest {
  protected:
    // Lin of `frame` rendered over a cleared color.
    std::vector<float> linOf(TestFrame& frame, const lightscatter::FrameDescription& d) {
        frame.resetColor();
        plugin().render(d);
        return frame.inscatter();
    }

    // Two spots' summed Lin against the sum of their single-light renders (unshadowed for a method
    // that casts no shadows).
    // `tolerance`: of the peak (froxels keep the integrated grid in float16).
    void checkSum(Method method, bool shadowed = true, double tolerance = 1e-6) {
        FrameSpec specA = sceneWith(spotOverGrille()), specB = sceneWith(secondSpot());
        specA.shadowed = specB.shadowed = shadowed;
        TestFrame a(dev(), specA);
        TestFrame b(dev(), specB);
        const auto settings = smallSettings(a.spec().screen);
        const auto da = a.description(method, lightscatter::Profile::Custom, settings);
        const auto db = b.description(method, lightscatter::Profile::Custom, settings);
        const auto linA = linOf(a, da);
        const auto linB = linOf(b, db);
        a.resetColor();
        const auto report = plugin().render(withLights(da, {input(da), input(db)}));
        const auto sum = a.inscatter();
        EXPECT_EQ(report.method, lightscatter::methodName(method));
        ASSERT_GT(peakOf(linA), 0.0);
        ASSERT_GT(peakOf(linB), 0.0);
        const double peak = peakOf(sum);
        double worst = 0;
        for (size_t i = 0; i < sum.size(); ++i) {
            if (i % 4 == 3) continue;
            const double expected = static_cast<double>(linA[i]) + static_cast<double>(linB[i]);
            worst = std::max(worst, std::fabs(static_cast<double>(sum[i]) - expected));
        }
        std::printf(
            "%s: two spots' summed Lin vs the sum of single renders: max |diff| %.3g, peak %.3g\n",
            lightscatter::methodName(method), worst, peak);
        EXPECT_LE(worst, tolerance * peak);
    }
};

TEST_F(LightsGpu, EpipolarTwoSpotsSumToTheSingleRenders) {
    checkSum(Method::Epipolar);
}
TEST_F(LightsGpu, BruteForceTwoSpotsSumToTheSingleRenders) {
    checkSum(Method::BruteForce);
}
// Every method takes a list of lights, one chain per light (issue #25).
TEST_F(LightsGpu, ConeMarchTwoSpotsSumToTheSingleRenders) {
    checkSum(Method::ConeMarch);
}
TEST_F(LightsGpu, PlanesTwoSpotsSumToTheSingleRenders) {
    checkSum(Method::Planes);
}
TEST_F(LightsGpu, BeamTreeAnalyticTwoSpotsSumToTheSingleRenders) {
    checkSum(Method::BeamTreeAnalytic);
}
TEST_F(LightsGpu, BeamTreeSamplingTwoSpotsSumToTheSingleRenders) {
    checkSum(Method::BeamTreeSampling);
}
TEST_F(LightsGpu, AnalyticTwoUnshadowedSpotsSumToTheSingleRenders) {
    checkSum(Method::Analytic, false);
}
// Froxels inject both spots into one grid: its integration is linear in the in-scattering.
TEST_F(LightsGpu, FroxelsTwoSpotsSumToTheSingleRenders) {
    checkSum(Method::Froxels, true, 2e-3);
}

// Froxels take every light into one grid: a frame whose method is froxels refuses a light that
// names another method, and a light that names froxels in an auto frame takes the others along.
TEST_F(LightsGpu, FroxelsMixWithNoOtherMethod) {
    TestFrame a(dev(), sceneWith(spotOverGrille()));
    TestFrame b(dev(), sceneWith(secondSpot()));
    const auto settings = smallSettings(a.spec().screen);
    const auto da = a.description(Method::Froxels, lightscatter::Profile::Custom, settings);
    const auto db = b.description(Method::Froxels, lightscatter::Profile::Custom, settings);
    auto second = input(db);
    second.method = Method::BruteForce;
    EXPECT_EQ(refusal(withLights(da, {input(da), second})),
              "lightscatter: lights[1].method = brute-force: froxels (lights[0]'s) takes every "
              "light of the frame into one grid and mixes with no other method; leave "
              "lights[1].method auto, or choose no froxels");
    auto automatic = withLights(da, {input(da), input(db)});
    automatic.method = Method::Auto;
    automatic.lights[1].method = Method::Froxels;
    const auto report = plugin().render(automatic);
    ASSERT_EQ(report.lights.size(), 2u);
    EXPECT_EQ(report.lights[0].method, "froxels");
    EXPECT_EQ(report.lights[1].method, "froxels");
    EXPECT_NE(report.lights[0].reason.find("froxels takes every light"), std::string::npos)
        << report.lights[0].reason;
}

// A light's own method overrides the frame's: the first spot by epipolar, the second by brute
// force in one frame equals the sum of each rendered alone with its method, and the report names
// both, per light and for the frame.
TEST_F(LightsGpu, EachLightTakesItsOwnMethod) {
    TestFrame a(dev(), sceneWith(spotOverGrille()));
    TestFrame b(dev(), sceneWith(secondSpot()));
    const auto settings = smallSettings(a.spec().screen);
    const auto da = a.description(Method::Epipolar, lightscatter::Profile::Custom, settings);
    const auto db = b.description(Method::BruteForce, lightscatter::Profile::Custom, settings);
    const auto linA = linOf(a, da);
    const auto linB = linOf(b, db);
    auto second = input(db);
    second.method = Method::BruteForce;
    a.resetColor();
    const auto report = plugin().render(withLights(da, {input(da), second}));
    const auto sum = a.inscatter();
    ASSERT_EQ(report.lights.size(), 2u);
    EXPECT_EQ(report.lights[0].method, "epipolar");
    EXPECT_EQ(report.lights[1].method, "brute-force");
    EXPECT_EQ(report.method, "epipolar+brute-force");
    double worst = 0;
    for (size_t i = 0; i < sum.size(); ++i)
        if (i % 4 != 3)
            worst = std::max(worst, std::fabs(static_cast<double>(sum[i]) - linA[i] - linB[i]));
    const double peak = peakOf(linA) + peakOf(linB);
    std::printf("epipolar + brute-force: max |diff| %.3g (peak %.3g)\n", worst, peak);
    EXPECT_LE(worst, 1e-6 * peak);
    // A wrong method for the second light (epipolar's Lin in its place) is told apart.
    a.resetColor();
    const auto both = linOf(a, withLights(da, {input(da), input(db)}));
    double apart = 0;
    for (size_t i = 0; i < sum.size(); ++i)
        if (i % 4 != 3) apart = std::max(apart, std::fabs(static_cast<double>(both[i]) - sum[i]));
    EXPECT_GT(apart, 1e-4 * peak);
}

// Each light's chain runs on its own settings: the second spot's coarse sampling (fewer slices and
// samples, a long initial step, no fix-up) gives a frame equal to the sum of the two single renders
// made with each light's settings, and a different one when the frame's settings rule both.
TEST_F(LightsGpu, EachLightTakesItsOwnSettings) {
    TestFrame a(dev(), sceneWith(spotOverGrille()));
    TestFrame b(dev(), sceneWith(secondSpot()));
    const auto fine = smallSettings(a.spec().screen);
    lightscatter::Settings coarse = fine;
    coarse.epipolar.slices = 32;
    coarse.epipolar.samplesPerSlice = 24;
    coarse.epipolar.initialSampleStep = 16;
    coarse.epipolar.fixup = false;
    const auto da = a.description(Method::Epipolar, lightscatter::Profile::Custom, fine);
    const auto db = b.description(Method::Epipolar, lightscatter::Profile::Custom, coarse);
    const auto linA = linOf(a, da);
    const auto linB = linOf(b, db);
    auto own = input(db);
    own.settings = coarse;
    auto differences = [&](const std::vector<lightscatter::LightInput>& lights) {
        const auto sum = linOf(a, withLights(da, lights));
        double worst = 0;
        for (size_t i = 0; i < sum.size(); ++i)
            if (i % 4 != 3)
                worst = std::max(worst, std::fabs(static_cast<double>(sum[i]) - linA[i] - linB[i]));
        return worst;
    };
    const double peak = peakOf(linA) + peakOf(linB);
    const double withOwn = differences({input(da), own});
    const double withFrames = differences({input(da), input(db)});  // both on `fine`
    std::printf("own settings: max |diff| %.3g; the frame's settings for both: %.3g (peak %.3g)\n",
                withOwn, withFrames, peak);
    EXPECT_LE(withOwn, 1e-6 * peak);
    EXPECT_GT(withFrames, 1e-3 * peak);  // the coarse settings change the second spot's Lin
}

TEST_F(LightsGpu, SunAndTwoSpotsInOneFrame) {
    TestFrame a(dev(), sceneWith(spotOverGrille()));
    TestFrame b(dev(), sceneWith(secondSpot()));
    TestFrame sun(dev(), sceneWith(sunThroughGrille()));
    const auto settings = smallSettings(a.spec().screen);
    const auto da = a.description(Method::Auto, lightscatter::Profile::Custom, settings);
    const auto db = b.description(Method::Auto, lightscatter::Profile::Custom, settings);
    const auto ds = sun.description(Method::Auto, lightscatter::Profile::Custom, settings);
    a.resetColor();
    const auto report = plugin().render(withLights(da, {input(ds), input(da), input(db)}));
    EXPECT_EQ(report.method, "epipolar");
    EXPECT_NE(report.reason.find("3 lights"), std::string::npos) << report.reason;
    const auto lin = a.inscatter();
    EXPECT_GT(peakOf(lin), 0.0);
    for (float v : lin) ASSERT_TRUE(std::isfinite(v));
}

// Issue #25's frame: a shadowed sun, two shadowed spots (one small) and four unshadowed point
// lights, auto choosing per light. The frame's Lin equals the sum of the seven single-light Lins,
// each rendered alone with the method auto picked for that light. The small spot has settings of
// its own, with more epipolar samples than this screen has pixels to serve (auto marches it per
// pixel), so that the frame mixes methods: a small spot is otherwise sampled as the others are,
// its lines within its screen rectangle (passes/epipolar/screen_share.h).
TEST_F(LightsGpu, AutoPicksPerLightAndTheFrameIsTheSumOfItsLights) {
    TestFrame a(dev(), sceneWith(spotOverGrille()));
    lightscatter::Light narrow = secondSpot();
    narrow.innerConeAngleDegrees = 6.0f;
    narrow.outerConeAngleDegrees = 9.0f;
    narrow.range = 5.0f;
    TestFrame b(dev(), sceneWith(narrow));
    TestFrame sun(dev(), sceneWith(sunThroughGrille()));
    const auto settings = smallSettings(a.spec().screen);
    const auto da = a.description(Method::Auto, lightscatter::Profile::Custom, settings);
    std::vector<lightscatter::LightInput> lights = {
        input(sun.description(Method::Auto, lightscatter::Profile::Custom, settings)), input(da),
        input(b.description(Method::Auto, lightscatter::Profile::Custom, settings))};
    lights[2].settings = settings;
    lights[2].settings->epipolar.slices = 1024;
    lights[2].settings->epipolar.samplesPerSlice = 1024;
    const glm::vec3 points[] = {
        {-1.5f, 1.0f, 0.5f}, {1.5f, 1.5f, -0.5f}, {0.0f, 2.5f, 1.0f}, {2.0f, 0.8f, 1.5f}};
    for (size_t k = 0; k < 4; ++k) {
        lightscatter::LightInput p;
        p.light.type = lightscatter::LightType::Point;
        p.light.position = {points[k].x, points[k].y, points[k].z};
        p.light.intensity = {2.0f + static_cast<float>(k), 3.0f, 4.0f - static_cast<float>(k)};
        p.light.range = k % 2 == 0 ? 2.5f : 1e30f;
        p.light.rangeFalloff = lightscatter::RangeFalloff::Window;
        lights.push_back(p);
    }
    a.resetColor();
    const auto report = plugin().render(withLights(da, lights));
    const auto frame = a.inscatter();
    ASSERT_EQ(report.lights.size(), lights.size());
    std::vector<double> sum(frame.size(), 0.0);
    double peak = 0;
    for (size_t i = 0; i < lights.size(); ++i) {
        const std::string method = report.lights[i].method;
        std::printf("lights[%zu]: %s (%s)\n", i, method.c_str(), report.lights[i].reason.c_str());
        ASSERT_NE(method, "none");
        lightscatter::FrameDescription d = withLights(da, {lights[i]});
        d.method = lightscatter::parseMethod(method).value();
        const auto lin = linOf(a, d);
        peak += peakOf(lin);
        for (size_t v = 0; v < lin.size(); ++v) sum[v] += lin[v];
    }
    double worst = 0;
    for (size_t v = 0; v < frame.size(); ++v)
        if (v % 4 != 3) worst = std::max(worst, std::fabs(static_cast<double>(frame[v]) - sum[v]));
    std::printf(
        "7 lights, auto per light (%s): max |diff| %.3g against the sum of single renders "
        "(peak %.3g)\n",
        report.method.c_str(), worst, peak);
    EXPECT_LE(worst, 1e-6 * peak);
    EXPECT_NE(report.method.find('+'), std::string::npos) << "one method for every light";
}

TEST_F(LightsGpu, ALightThatMissesTheViewAddsNoNode) {
    TestFrame a(dev(), sceneWith(spotOverGrille()));
    const auto settings = smallSettings(a.spec().screen);
    const auto da = a.description(Method::BruteForce, lightscatter::Profile::Custom, settings);
    lightscatter::LightInput away{spotOverGrille(), std::nullopt, std::nullopt};
    away.light.shadowMapSize = 0;
    away.light.position = {0.0f, 500.0f, 0.0f};  // far above, pointing up, short range
    away.light.direction = {0.0f, 1.0f, 0.0f};
    away.light.range = 1.0f;
    const auto one = plugin().render(withLights(da, {input(da), input(da)}));
    const auto two = plugin().render(withLights(da, {input(da), away}));
    EXPECT_NE(two.reason.find("1 reaching the view"), std::string::npos) << two.reason;
    EXPECT_LT(two.passNames.size(), one.passNames.size());
}

TEST_F(LightsGpu, RefusalsNameTheFields) {
    TestFrame a(dev(), sceneWith(spotOverGrille()));
    const auto settings = smallSettings(a.spec().screen);
    const auto da = a.description(Method::Epipolar, lightscatter::Profile::Custom, settings);
    // Both the single light and the list.
    auto both = withLights(da, {input(da), input(da)});
    both.shadowMap = da.shadowMap;
    const std::string b = refusal(both);
    EXPECT_NE(b.find("lights"), std::string::npos) << b;
    EXPECT_NE(b.find("shadowMap"), std::string::npos) << b;
    EXPECT_NE(b.find("never both"), std::string::npos) << b;
    // A broken light names its index and field.
    auto bad = withLights(da, {input(da), input(da)});
    bad.lights[1].light.innerConeAngleDegrees = bad.lights[1].light.outerConeAngleDegrees = 95.0f;
    const std::string h = refusal(bad);
    EXPECT_NE(h.find("lights[1].light.outerConeAngleDegrees"), std::string::npos) << h;
    auto missing = withLights(da, {input(da), input(da)});
    missing.lights[1].shadowMap.reset();
    const std::string m = refusal(missing);
    EXPECT_NE(m.find("lights[1].shadowMap is missing"), std::string::npos) << m;
    // A light's own settings are checked like the frame's custom, and named as the light's.
    auto ownBad = withLights(da, {input(da), input(da)});
    ownBad.lights[1].settings = settings;
    ownBad.lights[1].settings->epipolar.slices = 6;
    const std::string o = refusal(ownBad);
    EXPECT_NE(o.find("lights[1].settings.epipolar.slices"), std::string::npos) << o;
    // A method that cannot honour a light of the list refuses it, naming the light and itself.
    auto analytic = withLights(da, {input(da), input(da)});
    analytic.method = Method::Analytic;
    const std::string s = refusal(analytic);
    EXPECT_NE(s.find("lights[0]: method analytic"), std::string::npos) << s;
    // ... and so does a light's own method, overriding the frame's.
    auto own = withLights(da, {input(da), input(da)});
    own.lights[1].method = Method::Analytic;
    const std::string o1 = refusal(own);
    EXPECT_NE(o1.find("lights[1]: method analytic"), std::string::npos) << o1;
    // One light in the list is the single light, whatever the method.
    auto single = withLights(da, {input(da)});
    single.method = Method::ConeMarch;
    EXPECT_EQ(plugin().render(single).method, "cone-march");
}
