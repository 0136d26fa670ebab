// The epipolar method against brute force on small scenes, for each shadowed light type; min/max
// trees on and off; both interpolation modes; colored shafts; the composite.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plugin_fixture.h"

using namespace plugin_test;
using lightscatter::Method;

namespace {

// Fraction of pixels where the two images differ by more than `tolerance` x peak.
double fractionOver(const std::vector<float>& a, const std::vector<float>& b, double tolerance) {
    double peak = 0;
    for (size_t i = 0; i < b.size(); ++i)
        if (i % 4 != 3) peak = std::max(peak, static_cast<double>(b[i]));
    size_t over = 0;
    for (size_t i = 0; i < b.size(); i += 4)
        for (size_t c = 0; c < 3; ++c)
            if (std::fabs(static_cast<double>(a[i + c]) - b[i + c]) > tolerance * peak) {
                ++over;
                break;
            }
    return static_cast<double>(over) / static_cast<double>(b.size() / 4);
}

}  // namespace

class EpipolarGpu : public PluginGpuTest {
  protected:
    std::vector<float> render(TestFrame& frame, Method method, lightscatter::Settings settings,
                              lightscatter::FrameReport* report = nullptr) {
        frame.resetColor();
        const auto r = run(frame, method, settings);
        if (report) *report = r;
        return frame.inscatter();
    }
};

TEST_F(EpipolarGpu, SpotLightMatchesBruteForce) {
    TestFrame frame(dev(), sceneWith(spotOverGrille()));
    const auto settings = smallSettings(frame.spec().screen);
    lightscatter::FrameReport report;
    const auto brute = render(frame, Method::BruteForce, settings);
    const auto epi = render(frame, Method::Epipolar, settings, &report);
    const ErrorStats e = compare(epi, brute);
    std::printf("spot: mean %.2e rms %.2e max %.2e of peak %.3g\n", e.meanRelative, e.rmsRelative,
                e.maxRelative, e.peak);
    EXPECT_TRUE(ranPass(report, "ray march with min/max trees"));
    EXPECT_TRUE(ranPass(report, "min/max trees"));
    EXPECT_GT(e.peak, 0.0);
    EXPECT_EQ(e.nonFinite, 0u);
    // Bounds of docs/epipolar.md, measured 2e-4 / 2.4e-2 on lavapipe.
    EXPECT_LT(e.meanRelative, 1e-3);
    EXPECT_LT(e.maxRelative, 5e-2);
    EXPECT_LT(fractionOver(epi, brute, 1e-2), 0.02);
}

TEST_F(EpipolarGpu, DirectionalLightMatchesBruteForce) {
    TestFrame frame(dev(), sceneWith(sunThroughGrille()));
    const auto settings = smallSettings(frame.spec().screen);
    lightscatter::FrameReport report;
    const auto brute = render(frame, Method::BruteForce, settings);
    const auto epi = render(frame, Method::Epipolar, settings, &report);
    const ErrorStats e = compare(epi, brute);
    std::printf("directional: mean %.2e rms %.2e max %.2e\n", e.meanRelative, e.rmsRelative,
                e.maxRelative);
    // A directional light needs no point-light table.
    for (const auto& p : report.passNames) EXPECT_EQ(p.find("table"), std::string::npos) << p;
    EXPECT_GT(e.peak, 0.0);
    EXPECT_EQ(e.nonFinite, 0u);
    EXPECT_LT(e.meanRelative, 5e-3);
    EXPECT_LT(e.maxRelative, 8e-2);
}

TEST_F(EpipolarGpu, MinMaxTreesOnAndOffGiveTheSameImage) {
    for (const auto& light : {spotOverGrille(), sunThroughGrille()}) {
        TestFrame frame(dev(), sceneWith(light));
        auto settings = smallSettings(frame.spec().screen);
        settings.epipolar.initialSampleStep = 4;
        lightscatter::FrameReport withTrees, without;
        const auto a = render(frame, Method::Epipolar, settings, &withTrees);
        settings.epipolar.minMaxTrees = false;
        const auto b = render(frame, Method::Epipolar, settings, &without);
        EXPECT_TRUE(ranPass(withTrees, "min/max trees"));
        EXPECT_FALSE(ranPass(without, "min/max trees"));
        const ErrorStats e = compare(a, b);
        EXPECT_GT(e.peak, 0.0);
        // The trees are conservative: they decide exactly as visiting every sample would, so only
        // float rounding (and its float16 storage) separates the two images.
        EXPECT_LT(e.maxRelative, 1e-3) << "light type " << static_cast<int>(light.type);
    }
}

// Shadow maps of 1 to 3 texels hold no tree of two levels: they are marched texel by texel, with
// the trees asked for, and give what brute force gives (they used to fail inside the graph).
TEST_F(EpipolarGpu, TinyShadowMapsAreMarchedWithoutTrees) {
    for (uint32_t n : {1u, 2u, 3u, 4u}) {
        lightscatter::Light light = spotOverGrille();
        light.shadowMapSize = n;
        TestFrame frame(dev(), sceneWith(light));
        auto settings = smallSettings(frame.spec().screen);
        settings.shadowMapSize = n;
        ASSERT_TRUE(settings.epipolar.minMaxTrees);
        lightscatter::FrameReport report;
        const auto epi = render(frame, Method::Epipolar, settings, &report);
        const auto brute = render(frame, Method::BruteForce, settings);
        EXPECT_EQ(ranPass(report, "min/max trees"), n >= 4) << "shadow map " << n;
        const ErrorStats e = compare(epi, brute);
        EXPECT_EQ(e.nonFinite, 0u) << "shadow map " << n;
        EXPECT_GT(e.peak, 0.0) << "shadow map " << n;
        EXPECT_LT(e.meanRelative, 5e-3) << "shadow map " << n;
    }
}

TEST_F(EpipolarGpu, SeedInterpolationOfLinMatchesAwayFromTheLight) {
    TestFrame frame(dev(), sceneWith(sunThroughGrille()));
    auto settings = smallSettings(frame.spec().screen);
    const auto brute = render(frame, Method::BruteForce, settings);
    settings.epipolar.interpolation = lightscatter::Interpolation::Inscattering;
    const auto epi = render(frame, Method::Epipolar, settings);
    const ErrorStats e = compare(epi, brute);
    EXPECT_EQ(e.nonFinite, 0u);
    EXPECT_LT(e.meanRelative, 1e-2);
}

// Epipolar composites in its unwarp and fix-up (no composite pass): every pixel once, whether the
// unwarp or the fix-up serves it, and with fix-up off the unwarp alone, rendering without an
// attachment.
class EpipolarComposite : public EpipolarGpu, public testing::WithParamInterface<bool> {};

TEST_P(EpipolarComposite, AttenuatesTheEngineColorAndAddsLin) {
    FrameSpec spec = sceneWith(spotOverGrille());
    spec.background = 0.5f;
    TestFrame frame(dev(), spec);
    frame.resetColor();
    auto settings = smallSettings(spec.screen);
    settings.epipolar.fixup = GetParam();
    const auto report = run(frame, Method::Epipolar, settings);
    EXPECT_EQ(std::count(report.passNames.begin(), report.passNames.end(), "composite"), 0);
    EXPECT_EQ(std::count(report.passNames.begin(), report.passNames.end(), "fix-up ray march"),
              GetParam() ? 1 : 0);
    const auto lin = frame.inscatter();
    const auto color = frame.color();
    const lightscatter::Medium& m = spec.medium;
    double worst = 0;
    for (uint32_t y = 0; y < spec.screen.height; ++y)
        for (uint32_t x = 0; x < spec.screen.width; ++x) {
            const PixelRay r = pixelRay(spec.scene, spec.view, spec.screen.width,
                                        spec.screen.height, x, y, m.maxDistance);
            for (int c = 0; c < 3; ++c) {
                const size_t i = (size_t{y} * spec.screen.width + x) * 4 + static_cast<size_t>(c);
                const double betaT = m.betaR[c] + m.betaM[c] + m.sigmaA[c];
                const double want = 0.5 * std::exp(-betaT * r.S) + lin[i];
                worst = std::max(worst, std::fabs(color[i] - want) / want);
            }
        }
    EXPECT_LT(worst, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(FixUp, EpipolarComposite, testing::Bool(),
                         [](const testing::TestParamInfo<bool>& i) {
                             return i.param ? "On" : "Off";
                         });

TEST_F(EpipolarGpu, ColoredShaftsMatchBruteForceWithTreesOnAndOff) {
    FrameSpec spec = sceneWith(spotOverGrille());
    spec.coloredLight = true;
    TestFrame frame(dev(), spec);
    auto settings = smallSettings(spec.screen);
    lightscatter::FrameReport report;
    const auto brute = render(frame, Method::BruteForce, settings);
    const auto withTrees = render(frame, Method::Epipolar, settings, &report);
    settings.epipolar.minMaxTrees = false;
    const auto without = render(frame, Method::Epipolar, settings);
    const ErrorStats e = compare(withTrees, brute);
    EXPECT_GT(e.peak, 0.0);
    EXPECT_LT(e.meanRelative, 1e-3);
    EXPECT_LT(compare(withTrees, without).maxRelative, 1e-3);
    // The glass colors the shafts: somewhere red dominates blue by far, elsewhere the reverse.
    bool red = false, blue = false;
    for (size_t i = 0; i < brute.size(); i += 4) {
        red |= brute[i] > 3.0f * brute[i + 2] && brute[i] > 1e-3f * static_cast<float>(e.peak);
        blue |= brute[i + 2] > 3.0f * brute[i] && brute[i + 2] > 1e-3f * static_cast<float>(e.peak);
    }
    EXPECT_TRUE(red);
    EXPECT_TRUE(blue);
}

namespace {

// The slices and samples per slice the frame's report gives a light whose lines were cut to its
// screen rectangle; the settings' where it names none.
std::pair<uint32_t, uint32_t> lineCounts(const lightscatter::FrameReport& r,
                                         const lightscatter::Settings& s) {
    unsigned slices = 0, samples = 0;
    const size_t at = r.reason.find("screen rectangle: ");
    if (at == std::string::npos ||
        std::sscanf(r.reason.c_str() + at, "screen rectangle: %u slices of %u samples", &slices,
                    &samples) != 2)
        return {s.epipolar.slices, s.epipolar.samplesPerSlice};
    return {slices, samples};
}

// The slices of its border a light's lines take where the report names its wedge of the screen
// (passes/epipolar/screen_share.h, lineWindow), and the border's; {0, 0} where it names none.
std::pair<uint32_t, uint32_t> wedgeSlices(const lightscatter::FrameReport& r) {
    unsigned slices = 0, border = 0;
    const size_t at = r.reason.find("wedge of the screen: ");
    if (at == std::string::npos ||
        std::sscanf(r.reason.c_str() + at, "wedge of the screen: %u of the border's %u slices",
                    &slices, &border) != 2)
        return {0, 0};
    return {slices, border};
}

// Where a light's counts (what renderAt(degrees) reads from the report) first grew as its cone
// widened from `from` by `step` up to `to`: the counts there, and the angles either side.
struct CountStep {
    std::pair<uint32_t, uint32_t> first, grown;
    float below = 0.0f, above = 0.0f;
};
template <class Render>
CountStep widenUntilTheCountsGrow(Render renderAt, float from, float step, float to) {
    CountStep s;
    std::pair<uint32_t, uint32_t> counts = renderAt(from);
    s.first = counts;
    for (float degrees = from + step; degrees <= to && s.above == 0.0f; degrees += step) {
        const auto next = renderAt(degrees);
        // (0: the report names none, the light's whole border.)
        if (next.first != 0) {
            EXPECT_GE(next.first, counts.first)
                << degrees << " degrees: a wider cone, fewer slices";
        }
        if (next != counts) {
            s.below = degrees - step;
            s.above = degrees;
            s.grown = next;
        }
        counts = next;
    }
    return s;
}

// The counts stay the grown ones as the cone moves back and forth across the step, four times.
template <class Render>
void expectTheStepKept(Render renderAt, const CountStep& s) {
    for (int k = 0; k < 4; ++k) {
        EXPECT_EQ(renderAt(s.below), s.grown) << "back to " << s.below << " degrees, round " << k;
        EXPECT_EQ(renderAt(s.above), s.grown) << "at " << s.above << " degrees, round " << k;
    }
}

}  // namespace

// A spot's lines follow its share of the screen (passes/epipolar/screen_share.h): they grow at
// once when its screen rectangle grows past a step, and keep their count when it shrinks back by
// less than the margin, so that a light whose share hovers around a step does not switch its
// chain's configuration (a compiled graph) from frame to frame. The cone widens in half-degree
// steps until the counts grow, then moves between the last two angles. Measured at 64x48: 256 x
// 256 lines up to 6.5 degrees, 512 x 256 from 7.
TEST_F(EpipolarGpu, ASpotHoveringAtASizeStepKeepsItsLineCounts) {
    lightscatter::Light spot = spotOverGrille();
    spot.range = 8.0f;
    TestFrame frame(dev(), sceneWith(spot));
    lightscatter::Settings settings = smallSettings(frame.spec().screen);
    settings.epipolar.slices = 512;
    settings.epipolar.samplesPerSlice = 256;
    auto renderAt = [&](float degrees) {
        lightscatter::FrameDescription d =
            frame.description(Method::Epipolar, lightscatter::Profile::Custom, settings);
        d.light.innerConeAngleDegrees = d.light.outerConeAngleDegrees = degrees;
        return lineCounts(plugin().render(d), settings);
    };
    const CountStep s = widenUntilTheCountsGrow(renderAt, 3.0f, 0.5f, 30.0f);
    ASSERT_GT(s.above, 0.0f) << "the counts never grew from " << s.first.first << " x "
                             << s.first.second;
    std::printf("counts grow between %.1f and %.1f degrees: %u x %u -> %u x %u\n", s.below, s.above,
                s.first.first, s.first.second, s.grown.first, s.grown.second);
    EXPECT_LT(s.first.first, settings.epipolar.slices) << "the narrowest cone kept every slice";
    expectTheStepKept(renderAt, s);
    // (EpipolarScreenShare.AShareNearAStepKeepsTheFrameBeforesSizes: the counts do shrink once the
    // share is past the margin.)
}

// A spot seen from outside its cone takes the slices of its wedge of the screen, a step of its
// border (eighths, halvings below an eighth): the step is the chain's configuration, so as its
// rectangle's counts above, it grows at once and keeps its count while the wedge narrows back by
// less than the margin. The cone widens in one-degree steps until the wedge's slices grow, then
// moves between the last two angles. Measured: 128 of 1024 slices up to 4 degrees, 256 from 5;
// without the margin (kShrinkMargin 1) back at 4 degrees it takes 128 again, and fails.
TEST_F(EpipolarGpu, ASpotsWedgeHoveringAtAStepKeepsItsSlices) {
    lightscatter::Light spot = spotOverGrille();
    TestFrame frame(dev(), sceneWith(spot));
    lightscatter::Settings settings = smallSettings(frame.spec().screen);
    settings.epipolar.slices = 1024;
    settings.epipolar.samplesPerSlice = 256;
    auto renderAt = [&](float degrees) {
        lightscatter::FrameDescription d =
            frame.description(Method::Epipolar, lightscatter::Profile::Custom, settings);
        d.light.innerConeAngleDegrees = d.light.outerConeAngleDegrees = degrees;
        return wedgeSlices(plugin().render(d));
    };
    const CountStep s = widenUntilTheCountsGrow(renderAt, 2.0f, 1.0f, 40.0f);
    ASSERT_GT(s.first.first, 0u) << "a narrow cone seen from outside takes no wedge";
    EXPECT_LT(s.first.first, s.first.second);
    ASSERT_GT(s.above, 0.0f) << "the wedge never grew from " << s.first.first;
    std::printf("the wedge grows between %.0f and %.0f degrees: %u -> %u of %u slices\n", s.below,
                s.above, s.first.first, s.grown.first, s.grown.second);
    expectTheStepKept(renderAt, s);
}
