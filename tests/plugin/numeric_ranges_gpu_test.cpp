// Every number a frame carries, swept over the values single precision makes hard (0, the smallest
// normal, a subnormal, 1e-30, 1e30, +-FLT_MAX, NaN, +-inf) and the ends of the range lightscatter.h
// states for it: each is refused with a message naming the field, or renders finite Lin (and light
// where light must be) with every method that reads the field. 16x16 frames: what is at stake is
// the arithmetic, not the sampling.
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "plugin_fixture.h"
#include "support/projection.h"

using namespace plugin_test;
using lightscatter::FrameDescription;
using lightscatter::LightType;
using lightscatter::Method;
namespace limits = lightscatter::limits;

namespace {

constexpr VkExtent2D kScreen{16, 16};

enum class Base { Sun, Spot, UnshadowedSpot, Point };

const char* baseName(Base b) {
    switch (b) {
        case Base::Sun:
            return "sun";
        case Base::Spot:
            return "spot";
        case Base::UnshadowedSpot:
            return "unshadowed spot";
        case Base::Point:
            return "point";
    }
    return "?";
}

// The methods that take each light (beam-tree-analytic's closed form needs no shadow map).
std::vector<Method> methodsOf(Base b) {
    switch (b) {
        case Base::Sun:
            return {Method::Epipolar, Method::BruteForce, Method::ConeMarch, Method::Planes};
        case Base::Spot:
            return {Method::Epipolar, Method::BruteForce,       Method::ConeMarch,
                    Method::Planes,   Method::BeamTreeAnalytic, Method::BeamTreeSampling};
        case Base::UnshadowedSpot:
            return {Method::Analytic, Method::BeamTreeAnalytic};
        case Base::Point:
            return {Method::Epipolar, Method::BruteForce, Method::Analytic, Method::ConeMarch,
                    Method::Planes};
    }
    return {};
}

FrameSpec baseSpec(Base b) {
    lightscatter::Light light = b == Base::Sun ? sunThroughGrille() : spotOverGrille();
    if (b == Base::Point) {
        light = lightscatter::Light{};
        light.type = LightType::Point;
        light.position = {0.5f, 2.0f, 1.0f};
        light.intensity = {20.0f, 20.0f, 20.0f};
    }
    light.shadowMapSize = 64;
    FrameSpec s = sceneWith(light, kScreen);
    s.shadowed = b == Base::Sun || b == Base::Spot;
    return s;
}

lightscatter::Settings testSettings() {
    lightscatter::Settings s = smallSettings(kScreen);
    s.shadowMapSize = 64;
    s.planes.count = 32;
    s.coneMarch.samples = 16;
    return s;
}

struct Field {
    std::string name;  // as refusals name it
    std::vector<Base> bases;
    std::vector<Method> only;               // empty: every method of the base
    std::vector<double> ends;               // the range's ends (swept too)
    std::function<bool(double)> mayBeDark;  // where an accepted value may leave Lin all 0
    // Applied to the frame's spec before its images are made (what moves the shadow map), and to
    // the description; either may be empty.
    std::function<void(FrameSpec&, double)> spec;
    std::function<void(FrameDescription&, double)> desc;
    std::vector<double> values;  // empty: hardValues() and the ends
};

std::vector<double> hardValues() {
    const double inf = std::numeric_limits<double>::infinity();
    return {0.0,     FLT_MIN,  FLT_MIN / 64.0 /* a subnormal float */,   1e-30, 1e30,
            FLT_MAX, -FLT_MAX, std::numeric_limits<double>::quiet_NaN(), inf,   -inf};
}

float f32(double v) {
    return static_cast<float>(v);
}
void set3(lightscatter::Vec3& v, double x) {
    v = {f32(x), f32(x), f32(x)};
}
bool never(double) {
    return false;
}
bool below(double v, double limit) {
    return std::fabs(v) < limit;
}

std::vector<Field> fields() {
    const std::vector<Base> all{Base::Sun, Base::Spot, Base::UnshadowedSpot, Base::Point};
    const std::vector<Base> pointLike{Base::Spot, Base::UnshadowedSpot, Base::Point};
    const std::vector<Base> spot{Base::Spot};
    const double L = limits::kMaxLength;
    std::vector<Field> f;
    auto medium = [&](const char* name, std::vector<double> ends, std::function<bool(double)> dark,
                      std::function<void(lightscatter::Medium&, double)> g) {
        f.push_back({name, all, {}, ends, dark, {}, [g](FrameDescription& d, double v) {
                         g(d.medium, v);
                     }});
    };
    auto custom = [&](const char* name, std::vector<Base> bases, std::vector<Method> only,
                      std::vector<double> ends,
                      std::function<void(lightscatter::Settings&, double)> g) {
        f.push_back({name, bases, only, ends, never, {}, [g](FrameDescription& d, double v) {
                         g(d.custom, v);
                     }});
    };
    // Light: below 1e-29 W Lin is under the smallest normal float.
    f.push_back({"light.intensity",
                 all,
                 {},
                 {limits::kMaxIntensity},
                 [](double v) { return below(v, 1e-29); },
                 [](FrameSpec& s, double v) { set3(s.light.intensity, v); },
                 {}});
    // x of the light; a kilometre away and more the fog has put it out.
    f.push_back({"light.position",
                 pointLike,
                 {},
                 {-L, L},
                 [](double v) { return !below(v, 1e3); },
                 [](FrameSpec& s, double v) { s.light.position[0] = f32(v); },
                 {}});
    // Any finite non-zero length: the shadow map is made for the unit direction, the plugin
    // normalises what it is given.
    f.push_back({"light.direction",
                 all,
                 {},
                 {},
                 never,
                 [](FrameSpec& s, double v) {
                     if (std::isfinite(v) && v != 0.0) s.light.direction = {1.0f, -1.0f, 0.5f};
                 },
                 [](FrameDescription& d, double v) {
                     d.light.direction = {f32(v), f32(-v), f32(0.5 * v)};
                 }});
    f.push_back({"light.outerConeAngleDegrees",
                 {Base::Spot, Base::UnshadowedSpot},
                 {},
                 {limits::kMinConeAngleDegrees, 89.0},
                 [](double v) { return v < 1.0; },
                 [](FrameSpec& s, double v) {
                     s.light.outerConeAngleDegrees = f32(v);
                     s.light.innerConeAngleDegrees =
                         std::min(s.light.innerConeAngleDegrees, f32(v));
                 },
                 {}});
    f.push_back({"light.innerConeAngleDegrees",
                 {Base::Spot, Base::UnshadowedSpot},
                 {},
                 {limits::kMinConeAngleDegrees, 89.0},
                 [](double v) { return v < 1.0; },
                 [](FrameSpec& s, double v) {
                     s.light.innerConeAngleDegrees = f32(v);
                     s.light.outerConeAngleDegrees = 89.0f;
                 },
                 {}});
    // The light stands 6 m over the ground, the camera 9 m away.
    f.push_back({"light.range",
                 {Base::Spot, Base::UnshadowedSpot},
                 {},
                 {},
                 [](double v) { return v < 10.0; },
                 [](FrameSpec& s, double v) { s.light.range = f32(v); },
                 {}});
    // A radius of kilometres spreads the light's intensity so thin that Lin is under float16's
    // smallest value (6e-8), which the methods' screen targets hold.
    f.push_back({"light.radius",
                 pointLike,
                 {},
                 {limits::kMinRadius, L},
                 [](double v) { return v > 1e3; },
                 [](FrameSpec& s, double v) { s.light.radius = f32(v); },
                 {}});
    // Medium: a dense one puts out a point or spot light before its light reaches the camera;
    // the sun reaches every point undimmed (docs/model.md).
    const double C = limits::kMaxCoefficient;
    medium(
        "medium.betaR", {C}, [](double v) { return v > 1.0; },
        [](auto& m, double v) { set3(m.betaR, v); });
    medium(
        "medium.betaM", {C}, [](double v) { return v > 1.0; },
        [](auto& m, double v) { set3(m.betaM, v); });
    medium(
        "medium.sigmaA", {C}, [](double v) { return v > 1.0; },
        [](auto& m, double v) { set3(m.sigmaA, v); });
    medium("medium.g", {-0.999999, 0.999999}, never, [](auto& m, double v) { m.g = f32(v); });
    // Surfaces are never cut at the sky distance (docs/model.md), but the planes method's planes
    // (and beam-tree-sampling's) stop there: with a sky nearer than the scene, they leave it dark.
    medium(
        "medium.maxDistance", {L}, [](double v) { return v < 10.0; },
        [](auto& m, double v) { m.maxDistance = f32(v); });
    // Settings, with the methods that read each.
    custom("custom.epipolar.refinementThreshold", spot, {Method::Epipolar}, {},
           [](auto& s, double v) { s.epipolar.refinementThreshold = f32(v); });
    custom("custom.epipolar.inscatterRefinementThreshold", spot, {Method::Epipolar}, {},
           [](auto& s, double v) { s.epipolar.inscatterRefinementThreshold = f32(v); });
    custom("custom.epipolar.bilateralThreshold", spot, {Method::Epipolar}, {},
           [](auto& s, double v) { s.epipolar.bilateralThreshold = f32(v); });
    // A bias of half the depth range and more puts every point in shadow.
    f.push_back({"custom.shadowDepthBias",
                 spot,
                 {Method::Epipolar, Method::BruteForce, Method::ConeMarch, Method::Planes},
                 {-1.0, 1.0},
                 [](double v) { return v >= 0.5; },
                 {},
                 [](FrameDescription& d, double v) { d.custom.shadowDepthBias = f32(v); }});
    // A range far from Lin's (about 0.1 here) saturates the 8-bit target or rounds every share to
    // 0.
    f.push_back({"custom.planes.range",
                 spot,
                 {Method::Planes},
                 {1e-30},
                 [](double v) { return v < 1e-3 || v > 1e3; },
                 {},
                 [](FrameDescription& d, double v) {
                     d.custom.planes.target = lightscatter::PlaneTarget::Rgba8Channels;
                     d.custom.planes.range = f32(v);
                 }});
    custom("custom.planes.ambient", {Base::Spot, Base::Point},
           {Method::Planes, Method::BeamTreeSampling}, {limits::kMaxAmbient},
           [](auto& s, double v) { s.planes.ambient = f32(v); });
    custom("custom.noiseAmplitude", spot, {Method::Planes}, {1.0},
           [](auto& s, double v) { s.noiseAmplitude = f32(v); });
    custom("custom.noiseScale", spot, {Method::Planes},
           {limits::kMinNoiseScale, limits::kMaxNoiseScale}, [](auto& s, double v) {
               s.noiseAmplitude = 0.5f;
               s.noiseScale = f32(v);
           });
    custom("custom.noiseVelocity", spot, {Method::Planes}, {}, [](auto& s, double v) {
        s.noiseAmplitude = 0.5f;
        s.noiseVelocity = {f32(v), f32(v), f32(v), f32(v)};
    });
    // a0 of square kilometres spreads the light as a kilometre's radius does (light.radius).
    f.push_back({"custom.simplifiedA0",
                 {Base::UnshadowedSpot},
                 {Method::Analytic, Method::BeamTreeAnalytic},
                 {limits::kMaxSimplifiedA0},
                 [](double v) { return v > 1e6; },
                 {},
                 [](FrameDescription& d, double v) {
                     d.custom.lightModel = lightscatter::LightModel::Simplified;
                     d.custom.simplifiedA0 = f32(v);
                 }});
    custom("custom.simplifiedA1", {Base::UnshadowedSpot},
           {Method::Analytic, Method::BeamTreeAnalytic},
           {limits::kMinSimplifiedA1, limits::kMaxSimplifiedA1}, [](auto& s, double v) {
               s.lightModel = lightscatter::LightModel::Simplified;
               s.simplifiedA1 = f32(v);
           });
    // Whole numbers: what is not refused renders.
    const std::vector<double> counts{0.0, 1.0, 2.0, 3.0, 4294967295.0};
    // Two planes may both lie behind every surface.
    auto whole = [&](const char* name, std::vector<Method> only,
                     std::function<void(lightscatter::Settings&, uint32_t)> g) {
        f.push_back({name,
                     spot,
                     only,
                     {},
                     [](double v) { return v <= 2.0; },
                     {},
                     [g](FrameDescription& d, double v) { g(d.custom, static_cast<uint32_t>(v)); },
                     counts});
    };
    whole("custom.epipolar.slices", {Method::Epipolar},
          [](auto& s, uint32_t v) { s.epipolar.slices = v; });
    whole("custom.epipolar.samplesPerSlice", {Method::Epipolar},
          [](auto& s, uint32_t v) { s.epipolar.samplesPerSlice = v; });
    whole("custom.epipolar.initialSampleStep", {Method::Epipolar},
          [](auto& s, uint32_t v) { s.epipolar.initialSampleStep = v; });
    whole("custom.epipolar.fixupMaxSteps", {Method::Epipolar},
          [](auto& s, uint32_t v) { s.epipolar.fixupMaxSteps = v; });
    whole("custom.coneMarch.samples", {Method::ConeMarch},
          [](auto& s, uint32_t v) { s.coneMarch.samples = v; });
    whole("custom.planes.count", {Method::Planes}, [](auto& s, uint32_t v) { s.planes.count = v; });
    whole("custom.planes.blur", {Method::Planes}, [](auto& s, uint32_t v) { s.planes.blur = v; });
    // The camera's optional planes must agree with the projection (0: taken from it).
    f.push_back({"camera.nearPlane",
                 spot,
                 {Method::BruteForce},
                 {0.1},
                 never,
                 {},
                 [](FrameDescription& d, double v) { d.camera.nearPlane = f32(v); }});
    f.push_back({"camera.farPlane",
                 spot,
                 {Method::BruteForce},
                 {50.0},
                 never,
                 {},
                 [](FrameDescription& d, double v) { d.camera.farPlane = f32(v); }});
    f.push_back({"timeSeconds",
                 spot,
                 {Method::Planes},
                 {1e300, -1e300},
                 never,
                 {},
                 [](FrameDescription& d, double v) {
                     d.custom.noiseAmplitude = 0.5f;
                     d.timeSeconds = v;
                 }});
    return f;
}

size_t nonFinite(const std::vector<float>& v) {
    size_t n = 0;
    for (float x : v) n += std::isfinite(x) ? 0 : 1;
    return n;
}

size_t litValues(const std::vector<float>& lin) {
    size_t n = 0;
    for (size_t i = 0; i < lin.size(); ++i) n += i % 4 != 3 && lin[i] > 0.0f ? 1 : 0;
    return n;
}

std::string text(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace

class NumericRangesGpu : public PluginGpuTest {
  protected:
    // Renders `d` into `frame`: refused naming `field`, or finite (and lit unless `mayBeDark`).
    // Returns whether it rendered.
    bool judge(TestFrame& frame, const FrameDescription& d, const std::string& field,
               const std::string& what, bool mayBeDark) {
        frame.resetColor();
        try {
            plugin().render(d);
        } catch (const lightscatter::InvalidInput& e) {
            const std::string message = e.what();
            if (verbose_) std::printf("%-70s refused: %s\n", what.c_str(), message.c_str());
            EXPECT_NE(message.find(field), std::string::npos) << what << ": " << message;
            return false;
        }
        const std::vector<float> lin = frame.inscatter();
        const size_t bad = nonFinite(lin) + nonFinite(frame.color()), lit = litValues(lin);
        float peak = 0.0f;
        for (float x : lin) peak = std::max(peak, x);
        if (verbose_)
            std::printf("%-70s rendered: %zu non-finite, %zu lit, peak %g\n", what.c_str(), bad,
                        lit, peak);
        EXPECT_EQ(bad, 0u) << what << ": non-finite values in Lin or the composited color";
        if (!mayBeDark) {
            EXPECT_GT(lit, 0u) << what << ": Lin is all 0 where light must be";
        }
        return true;
    }
    const bool verbose_ = std::getenv("LS_VERBOSE") != nullptr;
};

TEST_F(NumericRangesGpu, EveryFieldIsRefusedOrRendersFinite) {
    size_t rendered = 0, refused = 0;
    for (const Field& field : fields()) {
        std::vector<double> values = field.values;
        if (values.empty()) {
            values = hardValues();
            values.insert(values.end(), field.ends.begin(), field.ends.end());
        }
        for (Base base : field.bases) {
            for (double value : values) {
                FrameSpec spec = baseSpec(base);
                if (field.spec) field.spec(spec, value);
                // A light the test cannot make a shadow map for is refused before it matters.
                std::unique_ptr<TestFrame> frame;
                FrameSpec usable = spec;
                if (!std::isfinite(usable.light.position[0]) ||
                    std::fabs(usable.light.position[0]) > 1e20f)
                    usable.light.position = baseSpec(base).light.position;
                frame = std::make_unique<TestFrame>(dev(), usable);
                for (Method method : field.only.empty() ? methodsOf(base) : field.only) {
                    bool applies = false;
                    for (Method m : methodsOf(base)) applies = applies || m == method;
                    if (!applies) continue;
                    FrameDescription d =
                        frame->description(method, lightscatter::Profile::Custom, testSettings());
                    d.light.position = spec.light.position;
                    if (field.desc) field.desc(d, value);
                    const std::string what = field.name + " = " + text(value) + " (" +
                                             baseName(base) + ", " +
                                             lightscatter::methodName(method) + ")";
                    if (judge(*frame, d, field.name, what, field.mayBeDark(value)))
                        ++rendered;
                    else
                        ++refused;
                }
            }
        }
    }
    std::printf("%zu frames rendered, %zu refused\n", rendered, refused);
}

// Each element of each matrix in turn: refused naming the matrix, or finite.
TEST_F(NumericRangesGpu, EveryMatrixElementIsRefusedOrRendersFinite) {
    TestFrame frame(dev(), baseSpec(Base::Spot));
    size_t rendered = 0;
    for (const char* field : {"camera.view", "camera.projection", "light.shadowViewProjection"})
        for (size_t i = 0; i < 16; ++i)
            for (double value : hardValues()) {
                FrameDescription d = frame.description(
                    Method::BruteForce, lightscatter::Profile::Custom, testSettings());
                lightscatter::Mat4& m = std::string(field) == "camera.view" ? d.camera.view
                                        : std::string(field) == "camera.projection"
                                            ? d.camera.projection
                                            : d.light.shadowViewProjection;
                m[i] = f32(value);
                const std::string what =
                    std::string(field) + "[" + std::to_string(i) + "] = " + text(value);
                // Setting an element moves what the frame shows: it may show nothing.
                rendered += judge(frame, d, field, what, true) ? 1 : 0;
            }
    std::printf("%zu frames rendered\n", rendered);
}

// Every bound at once, where it makes the most light: the products lightscatter.h's limits are
// derived from, for every method. Finite (a millimetre's mean free path may well put the light
// out before it reaches a pixel's ray: lit or not).
TEST_F(NumericRangesGpu, TheBrightestFrameTheRangesAllowIsFinite) {
    for (Base base : {Base::Sun, Base::Spot, Base::UnshadowedSpot, Base::Point}) {
        FrameSpec spec = baseSpec(base);
        set3(spec.light.intensity, limits::kMaxIntensity);
        spec.light.radius = limits::kMinRadius;
        // The camera looks at the light from close by, through the densest medium.
        spec.medium.betaM = {limits::kMaxCoefficient, limits::kMaxCoefficient,
                             limits::kMaxCoefficient};
        spec.medium.betaR = spec.medium.betaM;
        spec.medium.g = 0.999f;
        if (base != Base::Sun) {
            spec.view = lookAt({0.3f, 5.0f, 0.2f}, {0.3f, 0.0f, 0.2f}, 60.0f, 1.0f, 0.001f, 50.0f);
            spec.light.position = {0.3f, 4.99f, 0.2f};
        } else {
            spec.light.direction = {0.0f, -1.0f, 0.0f};
            spec.view = lookAt({0.0f, 5.0f, 0.0f}, {0.0f, 10.0f, 0.0f}, 60.0f, 1.0f, 0.001f, 50.0f);
        }
        TestFrame frame(dev(), spec);
        for (Method method : methodsOf(base))
            for (auto model :
                 {lightscatter::LightModel::Full, lightscatter::LightModel::Simplified}) {
                const bool simplifiedMethod =
                    method == Method::Analytic || method == Method::BeamTreeAnalytic;
                if (model == lightscatter::LightModel::Simplified && !simplifiedMethod) continue;
                lightscatter::Settings s = testSettings();
                s.lightModel = model;
                s.simplifiedA0 = 0.0f;
                s.simplifiedA1 = limits::kMinSimplifiedA1;
                if (method == Method::Planes || method == Method::BeamTreeSampling)
                    s.planes.ambient = limits::kMaxAmbient;
                const auto d = frame.description(method, lightscatter::Profile::Custom, s);
                judge(frame, d, "",
                      std::string(baseName(base)) + ", " + lightscatter::methodName(method) +
                          (model == lightscatter::LightModel::Simplified ? ", simplified" : ""),
                      true);
            }
    }
}
