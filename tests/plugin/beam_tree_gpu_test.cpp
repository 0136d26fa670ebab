// Seed 004's two methods on the GPU: without occluders beam-tree-analytic's lit pyramids are the
// whole light volume and the closed form must match the unshadowed model (with the camera inside
// the cone looking at the light too, and for a point light whose backplate lies past the far
// plane); with occluders both methods converge to brute force, and beam-tree-sampling gives what
// the planes method gives with the same planes; the simplified light model matches its closed form.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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

namespace {

// The shadowed spot over the grille, and the grille and the wall piece as outer boxes (thin: the
// grille is bars, not a solid, so no inner boxes).
std::vector<lightscatter::Occluder> grilleOccluders() {
    lightscatter::Occluder grille, wall;
    grille.outer.center = {0.0f, 3.0f, 0.0f};  // bars x in [-1.12, 1.12], z in [-1.6, 1.6]
    grille.outer.halfExtents = {1.13f, 0.01f, 1.61f};
    wall.outer.center = {-1.2f, 1.0f, 0.4f};
    wall.outer.halfExtents = {0.51f, 1.01f, 0.01f};
    return {grille, wall};
}

FrameSpec shadowedGrille() {
    FrameSpec spec;
    spec.screen = {48, 32};
    spec.view = defaultView(spec.screen);
    spec.light = spotOverGrille();
    spec.medium = fog();
    return spec;
}

lightscatter::Settings planeSettings(uint32_t planes) {
    lightscatter::Settings s = smallSettings();
    s.planes.count = planes;
    s.planes.target = lightscatter::PlaneTarget::Float32;
    return s;
}

std::vector<float> render(lightscatter::Plugin& p, TestFrame& frame, Method method,
                          const lightscatter::Settings& settings, std::string* chosen = nullptr) {
    frame.resetColor();
    auto desc = frame.description(method, lightscatter::Profile::Custom, settings);
    desc.occluders = grilleOccluders();
    const auto report = p.render(desc);
    if (chosen) *chosen = report.method;
    return frame.inscatter();
}

// Seed 004's simplified light model (Settings::lightModel) with non-default a0, a1.
constexpr double kA0 = 0.04, kA1 = 0.8;

lightscatter::Settings simplifiedSettings(VkExtent2D screen) {
    lightscatter::Settings s = smallSettings(screen);
    s.lightModel = lightscatter::LightModel::Simplified;
    s.simplifiedA0 = static_cast<float>(kA0);
    s.simplifiedA1 = static_cast<float>(kA1);
    return s;
}

// The largest |got - want| / want over the channels where want is above 1e-4 of the peak (the
// others: of the peak), and the mean error of the peak.
struct PixelErrors {
    double worstPerPixel = 0, meanOfPeak = 0;
    size_t nonFinite = 0;
};
PixelErrors perPixel(const std::vector<float>& got, const std::vector<float>& want) {
    const ErrorStats e = compare(got, want);
    PixelErrors p{0, e.meanRelative, e.nonFinite};
    for (size_t i = 0; i < want.size(); ++i) {
        if (i % 4 == 3) continue;
        const double w = want[i], d = std::fabs(static_cast<double>(got[i]) - w);
        p.worstPerPixel = std::max(p.worstPerPixel, w > 1e-4 * e.peak ? d / w : d / e.peak);
    }
    return p;
}

FrameSpec pointInView() {
    FrameSpec s = flatSpot();
    s.light.type = lightscatter::LightType::Point;
    s.light.position = {0.5f, 2.0f, 1.0f};
    return s;
}

}  // namespace

// Seed 004 5.3: clipping the planes to the tree's lit and uncertain space, and skipping the shadow
// map in lit space, adds no error to the planes method's; near the light's depth beam-tree-sampling
// also splits each plane into thinner ones whose slabs take the closed form (planes.frag's
// LS_SLAB). With the same planes it is then at least as close to brute force as the planes method.
TEST_F(BeamTreeGpu, SamplingWithClippingIsAtLeastAsGoodAsThePlanesWithTheSamePlanes) {
    TestFrame frame(dev(), shadowedGrille());
    lightscatter::Settings fine = smallSettings();
    fine.epipolar.samplesPerSlice = 1024;
    const std::vector<float> brute = render(plugin(), frame, Method::BruteForce, fine);
    for (uint32_t planes : {48u, 256u}) {
        std::string chosen;
        const std::vector<float> clipped =
            render(plugin(), frame, Method::BeamTreeSampling, planeSettings(planes), &chosen);
        EXPECT_EQ(chosen, "beam-tree-sampling");
        const std::vector<float> unclipped =
            render(plugin(), frame, Method::Planes, planeSettings(planes));
        const ErrorStats sampling = compare(clipped, brute), plain = compare(unclipped, brute);
        std::printf(
            "%u planes: mean error of brute force's peak: beam-tree-sampling %.2e, "
            "planes %.2e; the two differ by %.2e\n",
            planes, sampling.meanRelative, plain.meanRelative,
            compare(clipped, unclipped).meanRelative);
        EXPECT_EQ(sampling.nonFinite, 0u);
        // Measured: 1.2e-4 against 2.6e-3 (48 planes), 1.9e-4 against 4.5e-4 (256).
        EXPECT_LE(sampling.meanRelative, plain.meanRelative);
        // Drawing no planes, or the planes unshadowed (the lit draw's shader for all), fails.
        EXPECT_GT(compare(std::vector<float>(clipped.size(), 0.0f), brute).meanRelative,
                  10 * sampling.meanRelative);
        lightscatter::Settings unshadowed = planeSettings(planes);
        unshadowed.shadowSampling = false;
        EXPECT_GT(compare(render(plugin(), frame, Method::Planes, unshadowed), brute).meanRelative,
                  2 * sampling.meanRelative);
    }
}

// Both of seed 004's methods converge to brute force as their planes grow, on a shadowed frame
// whose tree has lit, uncertain and dark space; and beam-tree-sampling with few planes, whose near
// slabs then hold the light, stays close.
TEST_F(BeamTreeGpu, BothMethodsConvergeToBruteForceAsPlanesGrow) {
    TestFrame frame(dev(), shadowedGrille());
    lightscatter::Settings fine = smallSettings();
    fine.epipolar.samplesPerSlice = 1024;
    const std::vector<float> brute = render(plugin(), frame, Method::BruteForce, fine);
    // beam-tree-sampling's near slabs reach four spacings each side of the light's depth: with few
    // planes they hold most of the light in closed form, and its error is lowest there (measured
    // 0.00014 at 24 planes, 0.00016 at 48, 0.00021 at 96 and 192); from 96 planes on the midpoint
    // planes beyond them hold it, and their error falls as the planes grow.
    const std::pair<Method, std::vector<uint32_t>> sweeps[] = {
        {Method::BeamTreeSampling, {96u, 384u, 1536u}},
        {Method::BeamTreeAnalytic, {24u, 96u, 384u}}};
    for (const auto& [method, counts] : sweeps) {
        double previous = 1e30;
        for (uint32_t planes : counts) {
            const ErrorStats e =
                compare(render(plugin(), frame, method, planeSettings(planes)), brute);
            std::printf("%s, %3u planes: mean error %.5f of brute force's peak, max %.4f\n",
                        lightscatter::methodName(method), planes, e.meanRelative, e.maxRelative);
            EXPECT_EQ(e.nonFinite, 0u);
            EXPECT_LT(e.meanRelative, 0.8 * previous) << planes << " planes";
            previous = e.meanRelative;
        }
        // Measured: 9e-5 at 1536 planes (sampling), 3e-5 at 384 (analytic: most of the light is
        // lit space in closed form).
        EXPECT_LT(previous, 1e-3) << lightscatter::methodName(method);
    }
    // At 24 planes a near slab is longer than the cone is wide beside its apex. Measured 1.4e-4
    // and at worst 0.028 of the peak; with the slabs there cut to the cone at their own planes'
    // depths (the rays that cross it between two planes lost) 3.2e-4 and 0.146.
    const ErrorStats few =
        compare(render(plugin(), frame, Method::BeamTreeSampling, planeSettings(24)), brute);
    std::printf("beam-tree-sampling,  24 planes: mean error %.5f of brute force's peak, max %.4f\n",
                few.meanRelative, few.maxRelative);
    EXPECT_LT(few.meanRelative, 2e-4);
    EXPECT_LT(few.maxRelative, 0.05);
    // A result a broken method could give fails the final bound: black, or the light moved.
    EXPECT_GT(compare(std::vector<float>(brute.size(), 0.0f), brute).meanRelative, 10 * 1e-3);
    FrameSpec moved = shadowedGrille();
    moved.light.position[0] += 1.0f;
    TestFrame shifted(dev(), moved);
    EXPECT_GT(
        compare(render(plugin(), shifted, Method::BeamTreeSampling, planeSettings(384)), brute)
            .meanRelative,
        2e-3);
}

// Seed 004's simplified model without occluders: the lit pyramids carry its closed form (2.17) and
// match the float64 model's simplifiedClosedForm per pixel; analytic (seed 001's closed form, the
// same arctangent) honours it too. Measured, worst per pixel and channel (channels under 1e-4 of
// the peak: of the peak) and mean of the peak: beam-tree-analytic 3.3e-3 and 7.1e-7 (spot, at the
// cone's edge, as for the full model), 5.6e-5 and 4.8e-7 (point light); analytic, whose target is
// 16-bit, 2.2e-3 and 8.2e-6, 9.7e-4 and 1.9e-5. The full model's result of the same frame, a
// black image and the closed form shifted by one pixel are each far outside the bounds.
TEST_F(BeamTreeGpu, SimplifiedModelMatchesSeed004sClosedFormPerPixel) {
    struct Case {
        const char* what;
        FrameSpec spec;
    };
    const Case cases[] = {{"spot", flatSpot()}, {"point light in view", pointInView()}};
    constexpr double kPerPixel = 1e-2;
    auto meanBound = [](Method m) { return m == Method::Analytic ? 1e-4 : 3e-6; };
    for (const Case& c : cases) {
        TestFrame frame(dev(), c.spec);
        const std::vector<float> want = float64Simplified(frame, kA0, kA1);
        for (Method m : {Method::BeamTreeAnalytic, Method::Analytic}) {
            frame.resetColor();
            const auto report = run(frame, m, simplifiedSettings(c.spec.screen));
            EXPECT_EQ(report.method, lightscatter::methodName(m));
            // Isotropic and without extinction is the simplified model itself: nothing to warn
            // about.
            if (m == Method::Analytic) {
                EXPECT_EQ(report.notice, "");
            }
            const PixelErrors e = perPixel(frame.inscatter(), want);
            std::printf("simplified, %s, %s: worst per-pixel error %.2e, mean %.2e of the peak\n",
                        c.what, lightscatter::methodName(m), e.worstPerPixel, e.meanOfPeak);
            EXPECT_EQ(e.nonFinite, 0u);
            EXPECT_LT(e.worstPerPixel, kPerPixel) << c.what << ", " << lightscatter::methodName(m);
            EXPECT_LT(e.meanOfPeak, meanBound(m)) << c.what << ", " << lightscatter::methodName(m);
        }
        frame.resetColor();
        run(frame, Method::BeamTreeAnalytic);  // the full model
        const PixelErrors full = perPixel(frame.inscatter(), want);
        std::vector<float> shifted(want.size());  // one pixel to the right (the first column kept)
        for (size_t i = 0; i < want.size(); ++i)
            shifted[i] = (i / 4) % c.spec.screen.width ? want[i - 4] : want[i];
        const PixelErrors shift = perPixel(shifted, want);
        std::printf(
            "%s against the simplified closed form: the full model: worst %.2e, mean %.2e of the "
            "peak; shifted by a pixel: %.2e, %.2e\n",
            c.what, full.worstPerPixel, full.meanOfPeak, shift.worstPerPixel, shift.meanOfPeak);
        EXPECT_GT(full.worstPerPixel, 10 * kPerPixel) << c.what;
        EXPECT_GT(full.meanOfPeak, 10 * meanBound(Method::Analytic)) << c.what;
        EXPECT_GT(shift.worstPerPixel, 10 * kPerPixel) << c.what;
        EXPECT_GT(shift.meanOfPeak, 10 * meanBound(Method::Analytic)) << c.what;
        EXPECT_GT(perPixel(std::vector<float>(want.size(), 0.0f), want).worstPerPixel,
                  10 * kPerPixel);
    }
}

// An outer box around the light makes its whole volume uncertain, so the sampling planes (seed
// 002's planes shader, through light_at.glsl) integrate all of it: with the simplified model they
// converge to its closed form as the full model's converge to the float64 model.
TEST_F(BeamTreeGpu, SimplifiedModelInTheSamplingPlanes) {
    TestFrame frame(dev(), flatSpot());
    const auto& p = frame.light().position;
    lightscatter::Occluder around;
    around.outer.center = p;
    around.outer.halfExtents = {0.1f, 0.1f, 0.1f};
    auto render = [&](const lightscatter::Settings& s) {
        auto desc = frame.description(Method::BeamTreeAnalytic, lightscatter::Profile::Custom, s);
        desc.occluders = {around};
        frame.resetColor();
        const auto report = plugin().render(desc);
        EXPECT_EQ(report.method, "beam-tree-analytic");
        return frame.inscatter();
    };
    auto simplified = simplifiedSettings(frame.spec().screen);
    simplified.planes.count = 256;
    auto full = smallSettings(frame.spec().screen);
    full.planes.count = 256;
    const std::vector<float> want = float64Simplified(frame, kA0, kA1);
    const ErrorStats s = compare(render(simplified), want);
    const ErrorStats f = compare(render(full), float64Unshadowed(frame));
    const ErrorStats cross = compare(render(full), want);
    std::printf(
        "planes, 256: simplified %.2e, full %.2e of the peak against their own models; full "
        "against the simplified closed form %.2e\n",
        s.meanRelative, f.meanRelative, cross.meanRelative);
    EXPECT_EQ(s.nonFinite, 0u);
    EXPECT_LT(s.meanRelative, 2e-3);  // measured 4.2e-4 (the full model: 4.4e-4)
    EXPECT_GT(cross.meanRelative, 10.0 * s.meanRelative);
}

// The methods that integrate only the full model refuse the simplified one in one line naming the
// setting; auto picks analytic for an unshadowed light and beam-tree-analytic for a shadowed one.
TEST_F(BeamTreeGpu, MethodsThatDoNotHonourTheSimplifiedModelRefuseIt) {
    TestFrame frame(dev(), flatSpot());
    const auto settings = simplifiedSettings(frame.spec().screen);
    for (Method m : {Method::Epipolar, Method::BruteForce, Method::ConeMarch, Method::Planes}) {
        try {
            run(frame, m, settings);
            ADD_FAILURE() << lightscatter::methodName(m) << " accepted the simplified light model";
        } catch (const lightscatter::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find("custom.lightModel"), std::string::npos)
                << e.what();
        }
    }
    EXPECT_EQ(run(frame, Method::Auto, settings).method, "analytic");
    FrameSpec shadowed = flatSpot();
    shadowed.shadowed = true;
    TestFrame withShadows(dev(), shadowed);
    const auto report = run(withShadows, Method::Auto, settings);
    EXPECT_EQ(report.method, "beam-tree-analytic") << report.reason;
    EXPECT_NE(report.reason.find("simplified"), std::string::npos) << report.reason;
}
