// Seeds 001 (analytic) and 003 (cone-march) on the GPU, and auto's choices: analytic against the
// float64 closed form, cone-march converging to brute force, its no-sampling mode against the
// unshadowed closed form, and the method auto picks for a table of frames.
#include <cmath>
#include <cstdio>

#include "float64_model/closed_forms.h"
#include "model_conversion.h"
#include "plugin_fixture.h"

using namespace plugin_test;
using lightscatter::Method;

namespace {

// An isotropic medium, as seed 001 assumes (its extinction is ignored by the closed form and by the
// float64 function alike).
lightscatter::Medium isotropicFog() {
    lightscatter::Medium m;
    m.betaR = {0.0f, 0.0f, 0.0f};
    m.betaM = {0.02f, 0.03f, 0.04f};
    m.phase = lightscatter::MiePhase::Isotropic;
    m.maxDistance = 5000.0f;
    return m;
}

// A camera at the origin looking down -Z at a point light `distance` ahead, placed on the ray
// through pixel (7, 5) so that that ray goes through the light and its neighbours pass it at
// distance * (pixel angle) and more. No geometry: every ray is sky.
FrameSpec pointAhead(float distance) {
    FrameSpec s;
    s.scene = Scene{};
    s.screen = {32, 24};
    s.view = lookAt({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 60.0f, 32.0f / 24.0f, 0.05f, 4000.0f);
    const PixelRay r = pixelRay(s.scene, s.view, s.screen.width, s.screen.height, 7, 5, 1e30);
    const glm::dvec3 p = r.origin + r.dir * static_cast<double>(distance);
    s.light.type = lightscatter::LightType::Point;
    s.light.position = {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)};
    s.light.intensity = {50.0f, 40.0f, 30.0f};
    s.light.shadowMapSize = 0;
    s.shadowed = false;
    s.medium = isotropicFog();
    return s;
}

double worstRelative(const std::vector<float>& got, const std::vector<glm::dvec3>& want,
                     double& peak) {
    peak = 0;
    for (const auto& w : want) peak = std::max({peak, w.x, w.y, w.z});
    double worst = 0;
    for (size_t i = 0; i < want.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double g = got[i * 4 + static_cast<size_t>(c)], w = want[i][c];
            worst = std::max(worst,
                             std::isfinite(g) ? std::fabs(g - w) / std::max(w, 1e-6 * peak) : 1e30);
        }
    return worst;
}

double meanRelative(const std::vector<float>& a, const std::vector<float>& b) {
    double diff = 0, sum = 0;
    for (size_t i = 0; i < b.size(); ++i) {
        if (i % 4 == 3) continue;
        diff += std::fabs(static_cast<double>(a[i]) - b[i]);
        sum += std::fabs(static_cast<double>(b[i]));
    }
    return sum > 0 ? diff / sum : 0.0;
}

}  // namespace

class SeedMethodsGpu : public PluginGpuTest {};

// Rays from straight through the light to 1e3 m from it (the light 1e-2 to 1e3 m ahead, the
// screen's rays spreading up to half that distance away), against ls::ref's float64 closed form.
TEST_F(SeedMethodsGpu, AnalyticMatchesTheFloat64ClosedForm) {
    for (float distance : {0.01f, 1.0f, 30.0f, 2000.0f}) {
        TestFrame frame(dev(), pointAhead(distance));
        const FrameSpec& s = frame.spec();
        const auto report = run(frame, Method::Analytic);
        EXPECT_EQ(report.method, "analytic");
        const auto medium = refMedium(s.medium);
        const auto light = refLight(frame.light());
        std::vector<glm::dvec3> want;
        double nearest = 1e30, farthest = 0;
        for (uint32_t y = 0; y < s.screen.height; ++y)
            for (uint32_t x = 0; x < s.screen.width; ++x) {
                const PixelRay r = pixelRay(s.scene, s.view, s.screen.width, s.screen.height, x, y,
                                            s.medium.maxDistance);
                want.push_back(
                    ls::ref::pointArctanClosedForm(medium, light, {r.origin, r.dir, r.S}));
                const double h = glm::length(glm::cross(r.dir, r.origin - light.position));
                nearest = std::min(nearest, h);
                farthest = std::max(farthest, h);
            }
        double peak = 0;
        const double worst = worstRelative(frame.inscatter(), want, peak);
        std::printf(
            "analytic, light %g m ahead: rays pass %.1e to %.1e m from it, worst relative error "
            "%.2e\n",
            static_cast<double>(distance), nearest, farthest, worst);
        EXPECT_GT(peak, 0.0);
        EXPECT_LT(
            nearest,
            1e-4 * std::max(1.0, static_cast<double>(distance)));  // one ray through the light
        EXPECT_LT(worst, 1e-3) << "light " << distance << " m ahead";
    }
}

// More samples, closer to brute force: the error falls with the count and ends small.
TEST_F(SeedMethodsGpu, ConeMarchConvergesToBruteForce) {
    FrameSpec spec;
    spec.screen = {48, 32};
    spec.view = defaultView(spec.screen);
    spec.light = spotOverGrille();
    spec.medium = fog();
    TestFrame frame(dev(), spec);
    auto settings = smallSettings(spec.screen);
    frame.resetColor();
    run(frame, Method::BruteForce, settings);
    const auto brute = frame.inscatter();
    double previous = 1e30;
    for (uint32_t n : {4u, 16u, 64u, 256u}) {
        settings.coneMarch.samples = n;
        frame.resetColor();
        const auto report = run(frame, Method::ConeMarch, settings);
        EXPECT_EQ(report.method, "cone-march");
        const double e = meanRelative(frame.inscatter(), brute);
        std::printf("cone-march, %3u samples: mean relative error against brute force %.4f\n", n,
                    e);
        EXPECT_LT(e, previous) << n << " samples";
        previous = e;
    }
    EXPECT_LT(previous, 0.01);
}

// Seed 003's low-end mode: no shadow-map look-ups, so the unshadowed closed form (the table) is
// what it samples; with many samples the two agree within the midpoint rule's error.
TEST_F(SeedMethodsGpu, NoShadowSamplingMatchesTheUnshadowedClosedForm) {
    FrameSpec spec;
    spec.screen = {48, 32};
    spec.view = defaultView(spec.screen);
    spec.light = spotOverGrille();
    spec.medium = fog();
    TestFrame shadowed(dev(), spec);
    auto settings = smallSettings(spec.screen);
    settings.shadowSampling = false;
    settings.coneMarch.samples = 256;
    shadowed.resetColor();
    const auto report = run(shadowed, Method::ConeMarch, settings);
    EXPECT_NE(report.reason.find("no shadow-map sampling"), std::string::npos) << report.reason;
    const auto march = shadowed.inscatter();

    spec.shadowed = false;
    spec.light.shadowMapSize = 0;
    TestFrame open(dev(), spec);
    open.resetColor();
    run(open, Method::Epipolar, smallSettings(spec.screen));  // unshadowed: the closed form
    const auto closed = open.inscatter();
    double sum = 0;
    for (float v : closed) sum += v;
    EXPECT_GT(sum, 0.0);
    const double e = meanRelative(march, closed);
    std::printf("cone-march without shadow sampling, 256 samples, against the closed form: %.2e\n",
                e);
    EXPECT_LT(e, 0.01);

    // The methods that need the shadow map refuse the mode.
    settings.shadowSampling = false;
    for (Method m : {Method::Epipolar, Method::BruteForce}) {
        try {
            run(shadowed, m, settings);
            ADD_FAILURE() << lightscatter::methodName(m) << " accepted shadowSampling = false";
        } catch (const lightscatter::InvalidInput& err) {
            EXPECT_NE(std::string(err.what()).find("custom.shadowSampling"), std::string::npos)
                << err.what();
        }
    }
}

// What auto picks, and why, for a table of frames.
TEST_F(SeedMethodsGpu, AutoPicksByWhatTheFrameHolds) {
    struct Row {
        const char* what;
        FrameSpec spec;
        lightscatter::Settings settings;
        const char* method;
        const char* because;
    };
    auto base = [] {
        FrameSpec s;
        s.screen = {48, 32};
        s.view = defaultView(s.screen);
        s.light = spotOverGrille();
        s.medium = fog();
        return s;
    };
    std::vector<Row> rows;
    {
        Row r{"shadowed spot, small screen", base(), smallSettings({48, 32}), "brute-force",
              "per-pixel marching is cheaper"};
        r.settings.epipolar.slices = 1024;
        r.settings.epipolar.samplesPerSlice = 1024;
        rows.push_back(r);
    }
    rows.push_back({"shadowed spot, few epipolar samples", base(), smallSettings({48, 32}),
                    "epipolar", "epipolar sampling"});
    {
        Row r{"no shadow sampling", base(), smallSettings({48, 32}), "cone-march", "low-end mode"};
        r.settings.shadowSampling = false;
        rows.push_back(r);
    }
    {
        Row r{"unshadowed point, thin isotropic medium", pointAhead(5.0f), smallSettings({32, 24}),
              "analytic", "seed 001's closed form"};
        r.spec.medium.betaM = {1e-4f, 1e-4f, 1e-4f};
        rows.push_back(r);
    }
    {
        Row r{"unshadowed point, denser medium", pointAhead(5.0f), smallSettings({32, 24}),
              "epipolar", "over 1%"};
        r.spec.medium.betaM = {0.05f, 0.05f, 0.05f};
        rows.push_back(r);
    }
    {
        Row r{"unshadowed point, Mie lobe", pointAhead(5.0f), smallSettings({32, 24}), "epipolar",
              "isotropic"};
        r.spec.medium.betaM = {1e-4f, 1e-4f, 1e-4f};
        r.spec.medium.phase = lightscatter::MiePhase::CornetteShanks;
        rows.push_back(r);
    }
    {
        Row r{"zero intensity", base(), smallSettings({48, 32}), "none", "reaches no view ray"};
        r.spec.light.intensity = {0.0f, 0.0f, 0.0f};
        rows.push_back(r);
    }
    for (const Row& row : rows) {
        TestFrame frame(dev(), row.spec);
        frame.resetColor();
        const auto report = run(frame, Method::Auto, row.settings);
        std::printf("auto, %-40s -> %-11s (%s)\n", row.what, report.method.c_str(),
                    report.reason.c_str());
        EXPECT_EQ(report.method, row.method) << row.what;
        EXPECT_NE(report.reason.find(row.because), std::string::npos)
            << row.what << ": " << report.reason;
    }
}

// A light that can reach no view ray costs the frame nothing but the extinction: the same few
// passes, whatever the method.
TEST_F(SeedMethodsGpu, ALightThatReachesNoViewRayBuildsNoChain) {
    auto passesFor = [&](lightscatter::Light light, lightscatter::Medium medium, Method method) {
        FrameSpec s;
        s.screen = {32, 24};
        s.view = defaultView(s.screen);
        s.light = light;
        s.medium = medium;
        TestFrame frame(dev(), s);
        frame.resetColor();
        return run(frame, method).passNames;
    };
    lightscatter::Light away = spotOverGrille();
    away.position = {0.0f, 3.0f, 30.0f};  // behind the camera (at z = 9, looking towards -z)
    away.direction = {0.0f, 0.0f, 1.0f};  // and pointing further away
    away.range = 1e30f;                   // unbounded: culled by the view's reach
    lightscatter::Light dark = sunThroughGrille();
    dark.intensity = {0.0f, 0.0f, 0.0f};
    lightscatter::Medium clear = fog();
    clear.betaR = {0.0f, 0.0f, 0.0f};
    clear.betaM = {0.0f, 0.0f, 0.0f};
    clear.sigmaA = {0.01f, 0.01f, 0.01f};  // absorbs, scatters nothing
    for (Method m :
         {Method::Epipolar, Method::BruteForce, Method::ConeMarch, Method::Planes, Method::Auto}) {
        for (const auto& names : {passesFor(away, fog(), m), passesFor(dark, fog(), m),
                                  passesFor(sunThroughGrille(), clear, m)}) {
            std::string all;
            for (const auto& n : names) all += n + "; ";
            EXPECT_LE(names.size(), 3u) << lightscatter::methodName(m) << ": " << all;
            for (const auto& n : names)
                EXPECT_TRUE(n.find("upload") != std::string::npos ||
                            n.find("camera") != std::string::npos ||
                            n.find("composite") != std::string::npos)
                    << lightscatter::methodName(m) << ": " << n;
        }
    }
}
