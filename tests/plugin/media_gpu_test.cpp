// The non-uniform medium at the API (docs/model.md, "Non-uniform media"): each broken rule refused
// in one line naming its field, with nothing of the plugin's state changed; a homogeneous medium
// exactly as before (its density folded into the coefficients); the methods that cannot take a
// varying density refusing in one line and auto choosing one that can; and fog that moves every
// frame compiling nothing and refilling no table. Accuracy against the float64 model is
// tests/host/media_reference_gpu_test.cpp's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "plugin_fixture.h"

namespace plugin_test {
namespace {

using lightscatter::FogVolume;
using lightscatter::HeightFog;
using lightscatter::Medium;
using lightscatter::Method;

class MediaGpu : public PluginGpuTest {};

FrameSpec spotIn(Medium medium) {
    FrameSpec spec = sceneWith(spotOverGrille(), {48, 32});
    spec.medium = medium;
    return spec;
}

Medium heightFog(float baseHeight, float falloff) {
    Medium m = fog();
    m.heightFog = HeightFog{baseHeight, falloff};
    return m;
}

FogVolume box(float x, float density, float fade = 0.0f) {
    FogVolume v;
    v.center = {x, 1.5f, 0.0f};
    v.halfExtents = {1.0f, 1.5f, 1.0f};
    v.density = density;
    v.fade = fade;
    return v;
}

// The message of the InvalidInput `render` throws; fails when it throws none.
std::string refusalOf(const std::function<void()>& render) {
    try {
        render();
    } catch (const lightscatter::InvalidInput& e) {
        return e.what();
    }
    ADD_FAILURE() << "no refusal";
    return {};
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

double sumOf(const std::vector<float>& rgba) {
    double sum = 0.0;
    for (size_t i = 0; i < rgba.size(); ++i)
        if (i % 4 != 3) sum += rgba[i];
    return sum;
}

// What the composite multiplied the engine's constant color by, per pixel and channel.
std::vector<float> compositeTransmittance(TestFrame& frame) {
    std::vector<float> color = frame.color();
    const std::vector<float> lin = frame.inscatter();
    for (size_t i = 0; i < color.size(); ++i)
        if (i % 4 != 3) color[i] = (color[i] - lin[i]) / frame.spec().background;
    return color;
}

TEST_F(MediaGpu, EachBrokenRuleIsRefusedNamingItsFieldAndLeavesTheFrameAsItWas) {
    TestFrame frame(dev(), spotIn(heightFog(1.0f, 0.5f)));
    run(frame, Method::BruteForce);
    const std::vector<float> before = frame.inscatter();
    const lightscatter::Settings settings = smallSettings(frame.spec().screen);
    struct Case {
        std::function<void(Medium&)> spoil;
        std::string field;
    };
    const float nan = std::nanf("");
    const std::vector<Case> cases = {
        {[](Medium& m) { m.density = -1.0f; }, "medium.density"},
        {[&](Medium& m) { m.density = nan; }, "medium.density"},
        {[](Medium& m) { m.heightFog->falloff = -0.1f; }, "medium.heightFog.falloff"},
        {[](Medium& m) { m.heightFog->falloff = 2e4f; }, "medium.heightFog.falloff"},
        {[](Medium& m) { m.heightFog->baseHeight = 1e9f; }, "medium.heightFog.baseHeight"},
        {[](Medium& m) { m.fogVolumes.assign(65, box(0.0f, 1.0f)); }, "medium.fogVolumes holds 65"},
        {[](Medium& m) { m.fogVolumes = {box(0.0f, -2.0f)}; }, "medium.fogVolumes[0].density"},
        {[](Medium& m) { m.fogVolumes = {box(0.0f, 1.0f, -1.0f)}; }, "medium.fogVolumes[0].fade"},
        {[&](Medium& m) {
             m.fogVolumes = {box(0.0f, 1.0f)};
             m.fogVolumes[0].center[1] = nan;
         },
         "medium.fogVolumes[0].center"},
        {[](Medium& m) {
             m.fogVolumes = {box(0.0f, 1.0f), box(1.0f, 1.0f)};
             m.fogVolumes[1].halfExtents[2] = -1.0f;
         },
         "medium.fogVolumes[1].halfExtents"},
        {[](Medium& m) {
             m.fogVolumes = {box(0.0f, 1.0f)};
             m.fogVolumes[0].axes[1] = {0.0f, 2.0f, 0.0f};  // a scale, not a rotation
         },
         "medium.fogVolumes[0].axes[1] has length"},
        {[](Medium& m) {
             m.fogVolumes = {box(0.0f, 1.0f)};
             m.fogVolumes[0].axes[2] = {0.6f, 0.0f, 0.8f};  // not orthogonal to axes[0]
         },
         "medium.fogVolumes[0].axes[2] and medium.fogVolumes[0].axes[0]"},
        // Each density is in range, their sum times the coefficient is not.
        {[](Medium& m) { m.fogVolumes.assign(40, box(0.0f, 1000.0f)); },
         "medium.density plus the fog volumes' densities"},
    };
    for (const Case& c : cases) {
        lightscatter::FrameDescription d =
            frame.description(Method::BruteForce, lightscatter::Profile::Custom, settings);
        c.spoil(d.medium);
        const std::string message = refusalOf([&] { plugin().render(d); });
        EXPECT_NE(message.find(c.field), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    frame.resetColor();
    run(frame, Method::BruteForce);
    EXPECT_TRUE(sameBits(frame.inscatter(), before));
}

// A medium without height fog or volumes is homogeneous whatever its density: the density is the
// coefficients' factor, folded in before any shader sees it, so the frame is the one of the
// scaled coefficients, bit for bit, with every method's homogeneous pipelines.
TEST_F(MediaGpu, AHomogeneousMediumsDensityIsItsCoefficientsScaled) {
    Medium scaled = fog();
    for (int c = 0; c < 3; ++c) {
        scaled.betaR[c] *= 2.0f;
        scaled.betaM[c] *= 2.0f;
    }
    Medium dense = fog();
    dense.density = 2.0f;
    for (Method method : {Method::Epipolar, Method::BruteForce, Method::Froxels}) {
        TestFrame a(dev(), spotIn(scaled)), b(dev(), spotIn(dense));
        run(a, method);
        run(b, method);
        EXPECT_TRUE(sameBits(a.inscatter(), b.inscatter())) << lightscatter::methodName(method);
        EXPECT_TRUE(sameBits(a.color(), b.color())) << lightscatter::methodName(method);
    }
}

// Height fog whose base height is above everything the frame sees is density 1 everywhere: the
// non-uniform path must give the homogeneous frame (the sun's exactly given its optical depths,
// a spot's within its pieces' quadrature), and a thin layer must not.
TEST_F(MediaGpu, FogAboveEverythingIsTheHomogeneousMedium) {
    for (const lightscatter::Light& light : {spotOverGrille(), sunThroughGrille()}) {
        FrameSpec spec = sceneWith(light, {48, 32});
        spec.medium = fog();
        TestFrame homogeneous(dev(), spec);
        spec.medium = heightFog(500.0f, 0.3f);
        TestFrame high(dev(), spec);
        spec.medium = heightFog(0.5f, 3.0f);
        TestFrame thin(dev(), spec);
        for (Method method : {Method::BruteForce, Method::Epipolar}) {
            const std::string what =
                std::string(lightscatter::methodName(method)) +
                (light.type == lightscatter::LightType::Spot ? ", spot" : ", sun");
            for (TestFrame* f : {&homogeneous, &high, &thin}) {
                f->resetColor();
                run(*f, method);
            }
            const ErrorStats same = compare(high.inscatter(), homogeneous.inscatter());
            EXPECT_LT(same.meanRelative, 2e-3) << what;
            EXPECT_EQ(same.nonFinite, 0u) << what;
            // Most of the beam lies above the thin layer: far less light scatters.
            EXPECT_LT(sumOf(thin.inscatter()), 0.7 * sumOf(homogeneous.inscatter())) << what;
            // The composite's transmittance, (color - Lin) / background, per pixel.
            const std::vector<float> t = compositeTransmittance(high),
                                     t0 = compositeTransmittance(homogeneous);
            EXPECT_LT(compare(t, t0).maxRelative, 1e-4) << what;
            EXPECT_GT(compare(compositeTransmittance(thin), t0).maxRelative, 0.01) << what;
        }
    }
}

TEST_F(MediaGpu, TheMethodsWithoutMediaRefuseInOneLineAndAutoTakesOneThatCan) {
    Medium m = fog();
    m.fogVolumes = {box(0.0f, 2.0f, 0.3f)};
    FrameSpec spec = spotIn(m);
    spec.shadowed = false;
    TestFrame frame(dev(), spec);
    for (Method method : {Method::Analytic, Method::BeamTreeAnalytic}) {
        const std::string message = refusalOf([&] { run(frame, method); });
        EXPECT_NE(message.find("homogeneous medium only"), std::string::npos) << message;
        EXPECT_NE(message.find("medium.fogVolumes (1)"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    for (const lightscatter::MethodInfo& info : lightscatter::methodInfo()) {
        if (info.method == Method::Auto) continue;
        const bool refuses =
            info.method == Method::Analytic || info.method == Method::BeamTreeAnalytic;
        EXPECT_EQ(info.media, !refuses) << info.name;
    }
    // An unshadowed point light in an isotropic, thin medium is the analytic method's case when
    // the medium is homogeneous; with a fog volume auto must choose another.
    Medium thin;
    thin.betaR = {0.0f, 0.0f, 0.0f};
    thin.betaM = {3e-4f, 3e-4f, 3e-4f};  // optical depth 0.003 to the light
    thin.phase = lightscatter::MiePhase::Isotropic;
    FrameSpec point = spotIn(thin);
    point.shadowed = false;
    point.light.type = lightscatter::LightType::Point;
    TestFrame homogeneous(dev(), point);
    EXPECT_EQ(run(homogeneous, Method::Auto).method, "analytic");
    point.medium.fogVolumes = {box(0.0f, 2.0f)};
    TestFrame fogged(dev(), point);
    const lightscatter::FrameReport r = run(fogged, Method::Auto);
    EXPECT_EQ(r.method, "epipolar");
    EXPECT_NE(r.reason.find("non-uniform medium"), std::string::npos) << r.reason;
    // Seed 004's light model replaces the medium: refused with a non-uniform one, by any method.
    lightscatter::Settings s = smallSettings(frame.spec().screen);
    s.lightModel = lightscatter::LightModel::Simplified;
    const std::string message = refusalOf([&] { run(frame, Method::Planes, s); });
    EXPECT_NE(message.find("lightModel = simplified"), std::string::npos) << message;
}

// Fog as engines animate it: the density breathing, a volume sliding through the view and out of
// it, the height fog's base rising. After the first frame, nothing compiles and the point-light
// table is not refilled (it holds no extinction in a non-uniform medium).
TEST_F(MediaGpu, FogThatMovesEveryFrameCompilesNothingAndRefillsNoTable) {
    Medium m = heightFog(0.0f, 0.4f);
    m.fogVolumes = {box(-3.0f, 2.0f, 0.5f), box(2.0f, 1.0f)};
    FrameSpec spec = spotIn(m);
    spec.light.type = lightscatter::LightType::Point;
    spec.shadowed = false;
    TestFrame frame(dev(), spec);
    const lightscatter::Settings settings = smallSettings(frame.spec().screen);
    for (Method method :
         {Method::Epipolar, Method::BruteForce, Method::ConeMarch, Method::Froxels}) {
        std::vector<float> first;
        for (int k = 0; k < 12; ++k) {
            lightscatter::FrameDescription d =
                frame.description(method, lightscatter::Profile::Custom, settings);
            d.medium.density = 1.0f + 0.5f * std::sin(0.7f * static_cast<float>(k));
            d.medium.heightFog->baseHeight = 0.2f * static_cast<float>(k);
            d.medium.fogVolumes[0].center[0] =
                -3.0f + 4.0f * static_cast<float>(k);  // leaves the view after a few
            d.medium.fogVolumes[1].density = 0.25f * static_cast<float>(k);
            const lightscatter::FrameReport r = plugin().render(d);
            const std::string what =
                std::string(lightscatter::methodName(method)) + ", frame " + std::to_string(k);
            if (k > 0) {
                EXPECT_FALSE(r.graphCompiled) << what;
                EXPECT_TRUE(r.setupPasses.empty()) << what;
            }
            if (k == 0) first = frame.inscatter();
            if (k == 6) {
                EXPECT_FALSE(sameBits(frame.inscatter(), first)) << what;
            }
        }
    }
}

// Soft edges are compiled only where a volume has a fade (LS_MEDIA_FADES): giving one compiles
// once, the fade's code and the hard box's agree where the fade is thin, and a wide fade changes
// the image.
TEST_F(MediaGpu, AFadeCompilesOnceAndAThinOneRendersAsTheHardBox) {
    Medium m = heightFog(0.0f, 0.4f);
    m.fogVolumes = {box(-0.5f, 2.0f)};
    TestFrame frame(dev(), spotIn(m));
    const lightscatter::Settings settings = smallSettings(frame.spec().screen);
    const auto relativeL1 = [](const std::vector<float>& a, const std::vector<float>& b) {
        double diff = 0.0, sum = 0.0;
        for (size_t i = 0; i < a.size(); ++i) {
            if (i % 4 == 3) continue;
            diff += std::abs(double(a[i]) - double(b[i]));
            sum += std::abs(double(b[i]));
        }
        return diff / sum;
    };
    for (Method method :
         {Method::Epipolar, Method::BruteForce, Method::ConeMarch, Method::Froxels}) {
        const std::string name(lightscatter::methodName(method));
        lightscatter::FrameDescription d =
            frame.description(method, lightscatter::Profile::Custom, settings);
        plugin().render(d);
        const std::vector<float> hard = frame.inscatter();
        d.medium.fogVolumes[0].fade = 1e-4f;
        EXPECT_TRUE(plugin().render(d).graphCompiled) << name << ": the first fade";
        const std::vector<float> thin = frame.inscatter();
        d.medium.fogVolumes[0].fade = 0.6f;
        EXPECT_FALSE(plugin().render(d).graphCompiled) << name << ": a second fade";
        const std::vector<float> soft = frame.inscatter();
        EXPECT_LT(relativeL1(thin, hard), 2e-3) << name;
        EXPECT_GT(relativeL1(soft, hard), 2e-2) << name;
    }
}

}  // namespace
}  // namespace plugin_test
