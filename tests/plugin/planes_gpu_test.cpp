// The planes method (seed 002) on the GPU: convergence to the float64 model with the plane
// count, the 8-bit channel target against the float target within its quantisation, the cookie's
// stripes where brute force puts them, the noise's paths, and its refusals.
#include <cmath>
#include <cstdio>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>
#include "model_conversion.h"
#include "planes/plane_geometry.h"
#include "plugin_fixture.h"

using namespace plugin_test;
using lightscatter::Method;
using lightscatter::PlaneTarget;

namespace {

lightscatter::Settings planeSettings(uint32_t planes, PlaneTarget target) {
    lightscatter::Settings s = smallSettings();
    s.planes.count = planes;
    s.planes.target = target;
    return s;
}

double luminance(const float* p) {
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

}  // namespace

class PlanesGpu : public PluginGpuTest {};

// More planes, closer to the model: the midpoint rule's error falls like 1/planes with a float32
// target. A float16 target stops falling where its 11-bit mantissa rounds each plane's share.
TEST_F(PlanesGpu, ConvergesToTheFloat64ModelAsPlanesGrow) {
    TestFrame frame(dev(), flatSpot());
    const std::vector<float> want = float64Unshadowed(frame);
    double previous = 1e30;
    for (uint32_t planes : {32u, 64u, 128u, 256u}) {
        frame.resetColor();
        const auto report = run(frame, Method::Planes, planeSettings(planes, PlaneTarget::Float32));
        EXPECT_EQ(report.method, "planes");
        const ErrorStats e = compare(frame.inscatter(), want);
        frame.resetColor();
        run(frame, Method::Planes, planeSettings(planes, PlaneTarget::Float16));
        const ErrorStats half = compare(frame.inscatter(), want);
        std::printf(
            "planes, %3u planes: mean error (of the peak) %.5f float32, %.5f float16; max %.4f\n",
            planes, e.meanRelative, half.meanRelative, e.maxRelative);
        EXPECT_EQ(e.nonFinite, 0u);
        EXPECT_LT(e.meanRelative, 0.8 * previous) << planes << " planes";
        previous = e.meanRelative;
    }
    EXPECT_LT(previous, 0.002);
    // A broken result fails the bound: nothing at all, or the light a metre off.
    EXPECT_GT(compare(std::vector<float>(want.size(), 0.0f), want).meanRelative, 20 * previous);
    FrameSpec moved = flatSpot();
    moved.light.position[0] += 1.0f;
    TestFrame shifted(dev(), moved);
    run(shifted, Method::Planes, planeSettings(256, PlaneTarget::Float32));
    EXPECT_GT(compare(shifted.inscatter(), want).meanRelative, 5 * previous);
}

// Seed 002's 8-bit target: plane i in channel i mod 4, each blend rounded to 1/255 of a channel's
// quarter of the range. Against the float32 target (a gray medium and white light, so that the
// luminance carries everything): every pixel within half a step per plane, plus float error. The
// range lets one channel hold the brightest pixel whole: a ray past the apex gets most of its light
// from one or two planes, which a range of the peak itself would saturate.
TEST_F(PlanesGpu, EightBitChannelsHoldTheFloatTargetWithinTheirQuantisation) {
    FrameSpec spec = flatSpot();
    spec.light.intensity = {40.0f, 40.0f, 40.0f};
    spec.medium.betaR = {0.0f, 0.0f, 0.0f};
    spec.medium.betaM = {0.03f, 0.03f, 0.03f};
    TestFrame frame(dev(), spec);
    const uint32_t planes = 64;
    run(frame, Method::Planes, planeSettings(planes, PlaneTarget::Float32));
    const std::vector<float> full = frame.inscatter();
    double peak = 0;
    for (size_t i = 0; i < full.size(); i += 4) peak = std::max(peak, luminance(&full[i]));
    for (bool dither : {false, true}) {
        auto s = planeSettings(planes, PlaneTarget::Rgba8Channels);
        s.planes.range = static_cast<float>(4.4 * peak);
        s.planes.dither = dither;
        frame.resetColor();
        run(frame, Method::Planes, s);
        const std::vector<float> eight = frame.inscatter();
        const double step = s.planes.range / 4.0 / 255.0;
        // Rounding to nearest loses at most half a step per plane; stochastic rounding at most one.
        const double bound = planes * step * (dither ? 1.0 : 0.5) + 1e-3 * peak;
        double worst = 0, sumDiff = 0;
        for (size_t i = 0; i < full.size(); i += 4) {
            const double d = std::fabs(luminance(&eight[i]) - luminance(&full[i]));
            worst = std::max(worst, d);
            sumDiff += d;
        }
        const double mean = sumDiff / static_cast<double>(full.size() / 4);
        std::printf(
            "8-bit channels, %u planes, %s: worst %.4f, mean %.5f of a peak of %.4f (bound %.4f)\n",
            planes, dither ? "stochastic rounding" : "the seed's rounding", worst, mean, peak,
            bound);
        EXPECT_LE(worst, bound);
        EXPECT_GT(mean, 0.0);  // the target really is 8-bit
        if (dither) {
            EXPECT_LT(mean, 0.01 * peak);
        }
    }
}

// The cookie (the light-color image, stripes of red, green and blue glass): each lit pixel's
// dominant color is the one brute force gives it, so the stripes are where the light puts them.
TEST_F(PlanesGpu, TheCookiesStripesLandWhereBruteForcePutsThem) {
    FrameSpec spec = flatSpot();
    spec.shadowed = true;
    spec.coloredLight = true;
    spec.medium.betaR = {0.0f, 0.0f, 0.0f};
    spec.medium.betaM = {0.03f, 0.03f, 0.03f};
    TestFrame frame(dev(), spec);
    run(frame, Method::BruteForce);
    const std::vector<float> brute = frame.inscatter();
    frame.resetColor();
    run(frame, Method::Planes, planeSettings(256, PlaneTarget::Float32));
    const std::vector<float> planes = frame.inscatter();
    double peak = 0;
    for (size_t i = 0; i < brute.size(); i += 4) peak = std::max(peak, luminance(&brute[i]));
    auto dominant = [](const float* p) {
        return p[0] >= p[1] && p[0] >= p[2] ? 0 : (p[1] >= p[2] ? 1 : 2);
    };
    size_t lit = 0, same = 0;
    std::array<size_t, 3> bands{};
    for (size_t i = 0; i < brute.size(); i += 4) {
        if (luminance(&brute[i]) < 0.02 * peak) continue;
        ++lit;
        ++bands[static_cast<size_t>(dominant(&brute[i]))];
        same += dominant(&brute[i]) == dominant(&planes[i]);
    }
    std::printf(
        "cookie: %zu lit pixels (%zu red, %zu green, %zu blue), %zu with brute force's color\n",
        lit, bands[0], bands[1], bands[2], same);
    ASSERT_GT(lit, 50u);
    for (size_t b : bands) EXPECT_GT(b, lit / 10);  // all three stripes are in view
    EXPECT_GE(static_cast<double>(same), 0.9 * static_cast<double>(lit));
}

// Noise: amplitude 0 is exactly no noise; an engine noise of 1/2 in both layers is a density of
// exactly 1; the plugin's own noise changes the image and keeps its mean.
TEST_F(PlanesGpu, NoiseAmplitudeZeroIsTheModelAndNoiseKeepsTheMean) {
    const auto settings = planeSettings(64, PlaneTarget::Float32);
    TestFrame frame(dev(), flatSpot());
    run(frame, Method::Planes, settings);
    const std::vector<float> plain = frame.inscatter();

    FrameSpec halfSpec = flatSpot();
    halfSpec.noise.assign(16 * 16 * 4, 0.5f);
    TestFrame half(dev(), halfSpec);
    auto noisy = settings;
    noisy.noiseAmplitude = 1.0f;
    const auto report = run(half, Method::Planes, noisy);
    EXPECT_NE(report.reason.find("noise"), std::string::npos) << report.reason;
    EXPECT_LT(compare(half.inscatter(), plain).maxRelative, 1e-5);

    frame.resetColor();
    noisy.noiseAmplitude = 0.8f;
    noisy.noiseScale = 0.3f;
    const auto own = run(frame, Method::Planes, noisy);
    const std::vector<float> textured = frame.inscatter();
    double sumPlain = 0, sumNoisy = 0, peak = 0;
    for (size_t i = 0; i < plain.size(); i += 4) {
        sumPlain += luminance(&plain[i]);
        sumNoisy += luminance(&textured[i]);
        peak = std::max(peak, luminance(&plain[i]));
    }
    size_t lit = 0, changed = 0;
    for (size_t i = 0; i < plain.size(); i += 4) {
        if (luminance(&plain[i]) < 0.02 * peak) continue;
        ++lit;
        changed += std::fabs(luminance(&textured[i]) / luminance(&plain[i]) - 1.0) > 0.05;
    }
    std::printf(
        "own noise: mean changed by %.1f%%, %zu of %zu lit pixels changed by more than 5%%\n",
        100.0 * (sumNoisy / sumPlain - 1.0), changed, lit);
    EXPECT_GT(changed, lit / 5);                  // the noise is there
    EXPECT_NEAR(sumNoisy / sumPlain, 1.0, 0.25);  // and keeps the density's mean

    // Auto picks planes for a frame with noise; the methods that cannot sample it refuse it.
    frame.resetColor();
    EXPECT_EQ(run(frame, Method::Auto, noisy).method, "planes");
    for (Method m : {Method::Epipolar, Method::BruteForce, Method::ConeMarch, Method::Analytic}) {
        try {
            run(frame, m, noisy);
            ADD_FAILURE() << lightscatter::methodName(m) << " accepted noise";
        } catch (const lightscatter::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find("custom.noiseAmplitude"), std::string::npos)
                << e.what();
        }
    }
    (void)own;
}

// A depth image the planes cannot test against is refused in one line naming the field.
TEST_F(PlanesGpu, ADepthWithoutAttachmentUsageIsRefused) {
    FrameSpec spec = flatSpot();
    spec.depthAttachment = false;
    TestFrame frame(dev(), spec);
    try {
        run(frame, Method::Planes, planeSettings(32, PlaneTarget::Float16));
        ADD_FAILURE() << "planes accepted a depth image without DEPTH_STENCIL_ATTACHMENT";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("depth.usage"), std::string::npos) << e.what();
    }
    EXPECT_EQ(run(frame, Method::Epipolar).method, "epipolar");  // the other methods need no more
}

// Blur and the directional light's closed form outside the slab: finite, and a directional
// light's Lin converges like the spot's.
TEST_F(PlanesGpu, DirectionalLightAndBlurStayCloseToBruteForce) {
    FrameSpec spec = flatSpot();
    spec.light = sunThroughGrille();
    spec.shadowed = true;
    TestFrame frame(dev(), spec);
    run(frame, Method::BruteForce);
    const std::vector<float> brute = frame.inscatter();
    for (uint32_t blur : {0u, 2u}) {
        auto s = planeSettings(256, PlaneTarget::Float32);
        s.planes.blur = blur;
        frame.resetColor();
        run(frame, Method::Planes, s);
        const ErrorStats e = compare(frame.inscatter(), brute);
        std::printf("directional, 256 planes, blur %u: mean error %.4f of the peak, max %.3f\n",
                    blur, e.meanRelative, e.maxRelative);
        EXPECT_EQ(e.nonFinite, 0u);
        EXPECT_LT(e.meanRelative, blur ? 0.03 : 0.01);
    }
}

namespace {

// A camera at y = 1 looking down -z, and a spot 1 m behind it shining the same way, reaching 20 m.
std::tuple<ls::CameraParams, ls::LightParams, ls::MediumParams> placementScene() {
    ls::CameraParams camera;
    camera.view = glm::lookAt(glm::vec3(0, 1, 0), glm::vec3(0, 1, -1), glm::vec3(0, 1, 0));
    camera.projection = glm::perspective(glm::radians(60.0f), 1.5f, 0.1f, 500.0f);
    camera.nearPlane = 0.1f;
    camera.farPlane = 500.0f;
    ls::LightParams spot;
    spot.kind = ls::LightType::Spot;
    spot.position = {0, 1, 1};
    spot.direction = {0, 0, -1};
    spot.cosOuter = spot.cosInner = std::cos(0.5f);
    spot.range = 20.0f;
    ls::MediumParams medium;
    medium.betaM = glm::vec3(0.02f);
    return {camera, spot, medium};
}

}  // namespace

// Where the planes go (no GPU): a camera inside the spot's volume starts them at its near plane,
// and the seed's scaling of the count leaves a near volume all its planes and a far one fewer,
// never under an eighth.
TEST(PlanePlacement, FillsTheViewFromInsideAndScalesTheCountWithDistance) {
    auto [camera, spot, medium] = placementScene();
    ls::PlaneSettings settings;
    settings.planes = 128;
    settings.planeScaling = true;
    const ls::PlanePlacement inside = ls::placePlanes(camera, spot, medium, settings, 0.0);
    EXPECT_EQ(inside.planes, 128u);
    EXPECT_FLOAT_EQ(inside.push.boxMin.z, 0.1f);  // from the near plane
    EXPECT_NEAR(inside.push.boxMin.z + 128 * inside.push.boxMin.w, 19.0f,
                0.01f);  // to the range (z = 1 - 20)
    spot.position = {0, 1, -200};
    const ls::PlanePlacement far = ls::placePlanes(camera, spot, medium, settings, 0.0);
    EXPECT_LT(far.planes, 128u);
    EXPECT_GE(far.planes, 16u);
    settings.planeScaling = false;
    EXPECT_EQ(ls::placePlanes(camera, spot, medium, settings, 0.0).planes, 128u);
    spot.direction = {0, 0, 1};  // pointing away, the volume all behind the camera
    spot.position = {0, 1, 2};
    EXPECT_EQ(ls::placePlanes(camera, spot, medium, settings, 0.0).planes, 0u);
}

// Seed 004's dz: planes at most `spacing` apart along the view axis over the light's depth extent
// (here 18.9 m, the near plane to the range), however many that takes, within 2 to 4096.
TEST(PlanePlacement, ASpacingSetsTheCountFromTheDepthExtent) {
    auto [camera, spot, medium] = placementScene();
    ls::PlaneSettings settings;
    settings.planes = 128;
    for (const auto& [dz, planes] : {std::pair{0.5f, 38u}, {0.1f, 189u}, {100.0f, 2u}}) {
        settings.spacing = dz;
        const ls::PlanePlacement p = ls::placePlanes(camera, spot, medium, settings, 0.0);
        EXPECT_EQ(p.planes, planes) << "dz " << dz;
        EXPECT_LE(p.push.boxMin.w, dz) << "dz " << dz;
        EXPECT_NEAR(p.push.boxMin.w * float(p.planes), 18.9f, 0.01f) << "dz " << dz;
    }
    settings.spacing = 1e-6f;  // 19 million planes' worth: held at 4096
    EXPECT_EQ(ls::placePlanes(camera, spot, medium, settings, 0.0).planes, 4096u);
}

// beam-tree-sampling's near slabs (no GPU): every view ray that crosses a spot's cone between a
// slab's two depths passes through the slab's footprint on its middle plane, beside the apex too,
// where some of those rays miss the cone at the middle plane's own depth; a slab beside the apex
// covers a small part of the view; a slab past the range or before the apex has none.
TEST(PlanePlacement, ASpotSlabsFootprintHoldsEveryRayThatCrossesTheConeInIt) {
    auto [camera, spot, medium] = placementScene();
    spot.position = {0.3f, 3.0f, -8.0f};  // 8 m ahead, 2 m up, shining down
    spot.direction = {0, -1, 0};
    spot.cosOuter = spot.cosInner = std::cos(glm::radians(30.0f));
    spot.range = 10.0f;
    const glm::mat4 toWorld = glm::inverse(camera.view);
    const glm::vec3 eye(toWorld[3]);
    const float tx = 1.0f / camera.projection[0][0], ty = 1.0f / camera.projection[1][1];
    auto inCone = [&](const glm::vec3& p) {
        const glm::vec3 d = p - spot.position;
        const float r = glm::length(d);
        return r < spot.range && glm::dot(d, spot.direction) >= spot.cosOuter * r;
    };
    auto inside = [](const std::vector<glm::vec2>& poly, const glm::vec2& p) {
        for (size_t i = 0; i < poly.size(); ++i) {
            const glm::vec2 a = poly[i], e = poly[(i + 1) % poly.size()] - a;
            if (e.x * (p.y - a.y) - e.y * (p.x - a.x) < -1e-5f * glm::length(e)) return false;
        }
        return true;
    };
    for (const auto& [front, back] : {std::pair{7.9f, 8.0f},
                                      {8.0f, 8.1f},
                                      {7.95f, 8.05f},
                                      {8.3f, 8.5f},
                                      {0.0f, 7.95f},
                                      {5.0f, 11.0f}}) {
        const float z = 0.5f * (std::max(front, 0.1f) + back);
        const std::vector<glm::vec2> footprint =
            ls::spotSlabFootprint(camera, spot, medium, front, back, z);
        ASSERT_GE(footprint.size(), 3u) << front << "-" << back;
        int crossing = 0, missedAtMiddle = 0;
        for (int y = 0; y <= 120; ++y)
            for (int x = 0; x <= 120; ++x) {
                // A view ray by its point at view depth 1.
                const glm::vec2 at1((float(x) / 60.0f - 1.0f) * tx, (float(y) / 60.0f - 1.0f) * ty);
                const glm::vec3 dir = glm::vec3(toWorld * glm::vec4(at1, -1.0f, 0.0f));
                bool crosses = false;
                for (int k = 0; k <= 400 && !crosses; ++k)
                    crosses = inCone(eye + (front + (back - front) * float(k) / 400.0f) * dir);
                if (!crosses) continue;
                ++crossing;
                missedAtMiddle += inCone(eye + z * dir) ? 0 : 1;
                EXPECT_TRUE(inside(footprint, at1 * z))
                    << "slab " << front << "-" << back << ", ray " << x << "," << y;
            }
        EXPECT_GT(crossing, 0) << front << "-" << back;
        if (back - front < 0.5f) {
            // Beside the apex: a small part of the view, and rays the middle plane's cone misses.
            float area = 0.0f;
            for (size_t i = 0; i < footprint.size(); ++i) {
                const glm::vec2 a = footprint[i], b = footprint[(i + 1) % footprint.size()];
                area += 0.5f * (a.x * b.y - a.y * b.x);
            }
            EXPECT_GT(area, 0.0f);  // counter-clockwise
            EXPECT_LT(area, 0.3f * (4.0f * tx * ty * z * z)) << front << "-" << back;
            EXPECT_GT(missedAtMiddle, 0) << front << "-" << back;
        }
    }
    // Past the range (8 + 5.8 m deep at most), under the view (the pyramid reaches 2.2 m deep 10 m
    // down), and a point light's.
    EXPECT_TRUE(ls::spotSlabFootprint(camera, spot, medium, 18.5f, 19.0f, 18.75f).empty());
    EXPECT_TRUE(ls::spotSlabFootprint(camera, spot, medium, 2.0f, 3.0f, 2.5f).empty());
    spot.kind = ls::LightType::Point;
    EXPECT_TRUE(ls::spotSlabFootprint(camera, spot, medium, 7.9f, 8.0f, 7.95f).empty());
}
