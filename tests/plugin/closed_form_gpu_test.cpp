// Lights without shadows against docs/model.md's closed forms and the float64 numerical integral.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "float64_model/closed_forms.h"
#include "float64_model/inscatter_integral.h"
#include "model_conversion.h"
#include "plugin_fixture.h"

using namespace plugin_test;
using lightscatter::Method;

namespace {

// Worst relative error of the GPU's Lin against the float64 value, per pixel and channel, with a
// floor of `floor` x the image's peak so that near-zero pixels are judged absolutely.
struct Judged {
    double worst = 0, mean = 0, peak = 0;
};
Judged judge(TestFrame& frame, const std::vector<float>& lin, double floor) {
    const FrameSpec& s = frame.spec();
    const auto m = refMedium(s.medium);
    const auto l = refLight(frame.light());
    std::vector<glm::dvec3> expected(size_t{s.screen.width} * s.screen.height);
    Judged j;
    for (uint32_t y = 0; y < s.screen.height; ++y)
        for (uint32_t x = 0; x < s.screen.width; ++x) {
            const PixelRay r = pixelRay(s.scene, s.view, s.screen.width, s.screen.height, x, y,
                                        s.medium.maxDistance);
            const ls::ref::Ray ray{r.origin, r.dir, r.S};
            const glm::dvec3 e = l.type == ls::ref::Light::Directional
                                     ? ls::ref::directionalClosedForm(m, l, ray)
                                     : ls::ref::integrateInscatter(m, l, ray).value;
            expected[size_t{y} * s.screen.width + x] = e;
            j.peak = std::max({j.peak, e.x, e.y, e.z});
        }
    double sum = 0;
    for (size_t i = 0; i < expected.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double want = expected[i][c], got = lin[i * 4 + static_cast<size_t>(c)];
            const double err = std::fabs(got - want) / std::max(std::fabs(want), floor * j.peak);
            if (err > j.worst && std::getenv("LS_DEBUG_JUDGE")) {
                const uint32_t x = static_cast<uint32_t>(i % s.screen.width),
                               y = static_cast<uint32_t>(i / s.screen.width);
                const PixelRay r = pixelRay(s.scene, s.view, s.screen.width, s.screen.height, x, y,
                                            s.medium.maxDistance);
                const glm::dvec3 q = r.origin - l.position;
                std::printf("worst so far px %u,%u c%d got %.6g want %.6g  h %.4g sC %.4g S %.4g\n",
                            x, y, c, got, want, glm::length(glm::cross(r.dir, q)),
                            glm::dot(r.dir, q), r.S);
            }
            j.worst = std::max(j.worst, std::isfinite(got) ? err : 1e30);
            sum += err;
        }
    j.mean = sum / static_cast<double>(expected.size() * 3);
    return j;
}

FrameSpec unshadowed(lightscatter::Light light) {
    FrameSpec s;
    s.screen = {40, 30};
    s.view = defaultView(s.screen);
    s.light = light;
    s.light.shadowMapSize = 0;
    s.medium = fog();
    s.shadowed = false;
    return s;
}

}  // namespace

class ClosedFormGpu : public PluginGpuTest {};

TEST_F(ClosedFormGpu, UnshadowedDirectionalMatchesHoffmanPreetham) {
    TestFrame frame(dev(), unshadowed(sunThroughGrille()));
    const auto report = run(frame, Method::Epipolar);
    // No shadow map: the per-pixel closed form, nothing epipolar.
    for (const auto& name : report.passNames)
        EXPECT_EQ(name.find("epipolar"), std::string::npos) << name;
    const Judged j = judge(frame, frame.inscatter(), 1e-3);
    std::printf("directional: worst %.2e mean %.2e\n", j.worst, j.mean);
    EXPECT_GT(j.peak, 0.0);
    EXPECT_LT(j.worst, 2e-3);  // float32 math, float16 storage of the screen's Lin
}

TEST_F(ClosedFormGpu, UnshadowedPointLightMatchesTheIntegral) {
    lightscatter::Light l;
    l.type = lightscatter::LightType::Point;
    l.position = {0.6f, 2.0f, 1.0f};
    l.intensity = {30.0f, 25.0f, 20.0f};
    l.radius = 0.1f;
    TestFrame frame(dev(), unshadowed(l));
    const auto report = run(frame, Method::Epipolar);
    bool table = false;
    for (const auto& name : report.passNames) table |= name == "unshadowed in-scattering";
    EXPECT_TRUE(table);
    const Judged j = judge(frame, frame.inscatter(), 1e-3);
    std::printf("point: worst %.2e mean %.2e\n", j.worst, j.mean);
    EXPECT_GT(j.peak, 0.0);
    EXPECT_LT(j.mean, 1e-3);
    EXPECT_LT(j.worst, 1e-2);
}

TEST_F(ClosedFormGpu, UnshadowedSpotMatchesTheIntegral) {
    TestFrame frame(dev(), unshadowed(spotOverGrille()));
    run(frame, Method::Epipolar);
    const Judged j = judge(frame, frame.inscatter(), 1e-3);
    std::printf("spot: worst %.2e mean %.2e\n", j.worst, j.mean);
    EXPECT_GT(j.peak, 0.0);
    EXPECT_LT(j.mean, 1e-3);
    EXPECT_LT(j.worst, 3e-2);  // pixels whose ray grazes the cone
}

// Seed 004's hazy phase function (MiePhase::Hazy) through the same closed forms: a directional
// light (Hoffman-Preetham with the hazy lobe) and a point light (the table is integrated with it).
TEST_F(ClosedFormGpu, HazyPhaseMatchesTheFloat64Model) {
    FrameSpec sun = unshadowed(sunThroughGrille());
    sun.medium.phase = lightscatter::MiePhase::Hazy;
    TestFrame frame(dev(), sun);
    run(frame, Method::Epipolar);
    const Judged d = judge(frame, frame.inscatter(), 1e-3);
    lightscatter::Light l;
    l.type = lightscatter::LightType::Point;
    l.position = {0.6f, 2.0f, 1.0f};
    l.intensity = {30.0f, 25.0f, 20.0f};
    l.radius = 0.1f;
    FrameSpec point = unshadowed(l);
    point.medium.phase = lightscatter::MiePhase::Hazy;
    TestFrame pointFrame(dev(), point);
    run(pointFrame, Method::Epipolar);
    const Judged p = judge(pointFrame, pointFrame.inscatter(), 1e-3);
    std::printf("hazy: directional worst %.2e, point mean %.2e worst %.2e\n", d.worst, p.mean,
                p.worst);
    EXPECT_LT(d.worst, 2e-3);
    EXPECT_LT(p.mean, 1e-3);
    EXPECT_LT(p.worst, 1e-2);
    // The lobe is not Cornette-Shanks: the same frame with g's lobe is far off.
    sun.medium.phase = lightscatter::MiePhase::CornetteShanks;
    TestFrame other(dev(), sun);
    run(other, Method::Epipolar);
    EXPECT_GT(judge(frame, other.inscatter(), 1e-3).worst, 0.05);
}
