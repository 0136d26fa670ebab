// Every hard case of docs/model.md, for every method that applies: the frame renders without a
// validation message and every pixel of Lin and of the composited color is finite.
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <utility>

#include "plugin_fixture.h"
#include "support/projection.h"

using namespace plugin_test;
using lightscatter::LightType;
using lightscatter::Method;

namespace {

constexpr VkExtent2D kScreen{24, 16};
constexpr float kRefinement = 0.1f;  // Settings::inscatterRefinementThreshold when on

glm::vec3 eye() {
    return {0.0f, 2.5f, 9.0f};
}
glm::vec3 forward() {
    return glm::normalize(glm::vec3(0.0f, 1.5f, 0.0f) - eye());
}

// The world point at distance d along the ray through NDC (x, y) of the default view.
glm::vec3 throughNdc(const View& v, float x, float y, float d) {
    const glm::mat4 inv = glm::inverse(v.projection * v.view);
    glm::vec4 p = inv * glm::vec4(x, y, 0.5f, 1.0f);
    const glm::vec3 dir = glm::normalize(glm::vec3(p) / p.w - eye());
    return eye() + dir * d;
}

lightscatter::Vec3 v3(glm::vec3 v) {
    return {v.x, v.y, v.z};
}

FrameSpec base(lightscatter::Light light) {
    return sceneWith(light, kScreen);
}

lightscatter::Light spotAt(glm::vec3 position, glm::vec3 direction, float halfAngle = 35.0f) {
    lightscatter::Light l = spotOverGrille();
    l.position = v3(position);
    l.direction = v3(direction);
    l.innerConeAngleDegrees = l.outerConeAngleDegrees = halfAngle;
    return l;
}

lightscatter::Light pointAt(glm::vec3 position) {
    lightscatter::Light l;
    l.type = LightType::Point;
    l.position = v3(position);
    l.intensity = {20, 20, 20};
    return l;
}

lightscatter::Light sun(glm::vec3 direction) {
    lightscatter::Light l = sunThroughGrille();
    l.direction = v3(direction);
    return l;
}

struct HardCase {
    const char* name;
    std::function<FrameSpec()> make;
};

std::vector<HardCase> hardCases() {
    const View view = defaultView(kScreen);
    std::vector<HardCase> c;
    c.push_back({"light in the screen's centre", [=] {
                     return base(spotAt(throughNdc(view, 0, 0, 5), {0, -1, -0.3f}));
                 }});
    c.push_back({"light at a corner", [=] {
                     return base(spotAt(throughNdc(view, -1, -1, 6), {0.2f, -1, 0}));
                 }});
    c.push_back({"light exactly on an edge", [=] {
                     return base(spotAt(throughNdc(view, 1, 0, 6), {-0.3f, -1, 0}));
                 }});
    c.push_back({"light outside the screen", [=] {
                     return base(spotAt(throughNdc(view, 2.5f, 0.3f, 6), {-0.5f, -1, 0}));
                 }});
    c.push_back({"light behind the camera", [=] {
                     return base(
                         spotAt(eye() - forward() * 3.0f + glm::vec3(0, 1, 0), forward(), 40));
                 }});
    c.push_back({"spot light at the camera", [=] { return base(spotAt(eye(), forward(), 30)); }});
    c.push_back({"point light at the camera", [=] { return base(pointAt(eye())); }});
    c.push_back({"ray through a point light", [=] {
                     // On the ray through the centre of pixel (12, 8).
                     const float x = (12.5f / kScreen.width) * 2 - 1,
                                 y = (8.5f / kScreen.height) * 2 - 1;
                     return base(pointAt(throughNdc(view, x, y, 4)));
                 }});
    c.push_back({"directional light along the view axis", [=] { return base(sun(forward())); }});
    c.push_back({"looking into a directional light", [=] { return base(sun(-forward())); }});
    c.push_back({"directional light across the view axis", [=] { return base(sun({1, 0, 0})); }});
    c.push_back({"camera inside the spot cone", [=] {
                     return base(spotAt(eye() + glm::vec3(0, 3, 0), {0, -1, -0.4f}, 60));
                 }});
    c.push_back({"camera on the spot cone", [=] {
                     // Apex above the camera, axis tilted so that the camera lies on the surface.
                     const float a = glm::radians(30.0f);
                     const glm::vec3 apex = eye() + glm::vec3(0, 4, 0);
                     const glm::vec3 axis(std::sin(a), -std::cos(a),
                                          0);  // 30 deg from the way down
                     return base(spotAt(apex, axis, 30));
                 }});
    c.push_back({"sky at the far plane", [=] {
                     FrameSpec s = base(spotOverGrille());
                     s.scene.quads.clear();
                     return s;
                 }});
    c.push_back({"infinite far plane", [=] {
                     FrameSpec s = base(sunThroughGrille());
                     s.view = lookAt(eye(), {0, 1.5f, 0}, 60, 1.5f, 0.1f, 50, false, true);
                     s.scene.quads.resize(1);
                     return s;
                 }});
    c.push_back({"reversed z", [=] {
                     FrameSpec s = base(spotOverGrille());
                     s.view = lookAt(eye(), {0, 1.5f, 0}, 60, 1.5f, 0.1f, 50, true, false);
                     return s;
                 }});
    c.push_back({"reversed z, infinite far plane, reversed shadow map", [=] {
                     FrameSpec s = base(spotOverGrille());
                     s.view = lookAt(eye(), {0, 1.5f, 0}, 60, 1.5f, 0.1f, 50, true, true);
                     s.light.shadowReversedZ = true;
                     return s;
                 }});
    c.push_back({"thin medium over kilometres", [=] {
                     FrameSpec s = base(sunThroughGrille());
                     s.medium.betaR = {2e-6f, 4e-6f, 8e-6f};
                     s.medium.betaM = {4e-6f, 4e-6f, 4e-6f};
                     s.medium.maxDistance = 8000;
                     s.view = lookAt(eye(), {0, 1.5f, 0}, 60, 1.5f, 0.1f, 8000);
                     return s;
                 }});
    c.push_back({"dense medium", [=] {
                     FrameSpec s = base(spotOverGrille());
                     s.medium.betaM = {2.0f, 2.0f, 2.0f};
                     return s;
                 }});
    c.push_back({"zero extinction in a channel", [=] {
                     FrameSpec s = base(pointAt({0.5f, 2, 1}));
                     s.medium.betaR = {0, 0.01f, 0.02f};
                     s.medium.betaM = {0, 0.02f, 0.02f};
                     return s;
                 }});
    c.push_back({"zero extinction in a channel, shadowed", [=] {
                     FrameSpec s = base(spotOverGrille());
                     s.medium.betaR = {0, 0.01f, 0.02f};
                     s.medium.betaM = {0, 0.02f, 0.02f};
                     return s;
                 }});
    c.push_back({"NaN depth texels", [=] {
                     FrameSpec s = base(spotOverGrille());
                     s.depthOverride = renderDepth(s.scene, s.view, kScreen.width, kScreen.height);
                     for (size_t i = 0; i < s.depthOverride.size(); i += 7)
                         s.depthOverride[i] = std::numeric_limits<float>::quiet_NaN();
                     return s;
                 }});
    c.push_back({"shadow map and screen not powers of two", [=] {
                     FrameSpec s = base(spotOverGrille());
                     s.screen = {37, 23};
                     s.view = defaultView(s.screen);
                     s.light.shadowMapSize = 100;
                     return s;
                 }});
    c.push_back({"1x1 screen", [=] {
                     FrameSpec s = base(spotOverGrille());
                     s.screen = {1, 1};
                     s.view = defaultView(s.screen);
                     return s;
                 }});
    c.push_back({"very wide screen", [=] {
                     FrameSpec s = base(sunThroughGrille());
                     s.screen = {256, 4};
                     s.view = defaultView(s.screen);
                     return s;
                 }});
    return c;
}

size_t countNonFinite(const std::vector<float>& v) {
    size_t n = 0;
    for (float x : v) n += std::isfinite(x) ? 0 : 1;
    return n;
}

}  // namespace

class HardCasesGpu : public PluginGpuTest {};

TEST_F(HardCasesGpu, EveryCaseGivesFinitePixelsWithEveryMethod) {
    for (const HardCase& hard : hardCases()) {
        TestFrame frame(dev(), hard.make());
        // Epipolar twice: without and with refinement on in-scattering differences.
        for (auto [method, refinement] :
             {std::pair{Method::Epipolar, 0.0f}, std::pair{Method::Epipolar, kRefinement},
              std::pair{Method::BruteForce, 0.0f}}) {
            frame.resetColor();
            auto settings = smallSettings(frame.spec().screen);
            settings.shadowMapSize = frame.light().shadowMapSize;
            settings.epipolar.inscatterRefinementThreshold = refinement;
            const auto report = run(frame, method, settings);
            const auto lin = frame.inscatter();
            const auto color = frame.color();
            EXPECT_EQ(countNonFinite(lin), 0u)
                << hard.name << " (" << lightscatter::methodName(method) << ")";
            EXPECT_EQ(countNonFinite(color), 0u)
                << hard.name << " (" << lightscatter::methodName(method) << ")";
            float most = 0;
            for (float x : lin) most = std::max(most, x);
            EXPECT_GE(most, 0.0f) << hard.name;
            EXPECT_FALSE(report.passNames.empty()) << hard.name;
        }
    }
}

// The same cases at a size where the epipolar image can be judged: it must stay within the bound
// docs/epipolar.md states for hard cases (mean error 2% of the frame's peak Lin). The worst
// measured (lavapipe, 48x32): the light behind the camera, 0.88%; a spot light at the camera, where
// every ray projects to a point of the shadow map and is marched on its own, 0.45%.
TEST_F(HardCasesGpu, EpipolarStaysCloseToBruteForce) {
    for (const HardCase& hard : hardCases()) {
        FrameSpec spec = hard.make();
        if (spec.screen.width != kScreen.width || !spec.depthOverride.empty()) continue;
        spec.screen = {48, 32};
        // The case's own projection (planes, reversed or infinite depth) at the new aspect: the
        // plugin reads the planes from it and refuses flags that disagree.
        const View& v = spec.view;
        spec.view.projection =
            testing_support::vulkanPerspective(glm::radians(60.0f), 48.0f / 32.0f, v.nearPlane,
                                               v.farPlane, v.reversedZ, v.infiniteFar);
        TestFrame frame(dev(), spec);
        auto settings = smallSettings(frame.spec().screen);
        settings.shadowMapSize = frame.light().shadowMapSize;
        frame.resetColor();
        run(frame, Method::BruteForce, settings);
        const auto brute = frame.inscatter();
        // The bound holds with refinement on in-scattering differences too.
        for (float refinement : {0.0f, kRefinement}) {
            settings.epipolar.inscatterRefinementThreshold = refinement;
            frame.resetColor();
            run(frame, Method::Epipolar, settings);
            const ErrorStats e = compare(frame.inscatter(), brute);
            EXPECT_EQ(e.nonFinite, 0u) << hard.name << ", refinement " << refinement;
            EXPECT_LT(e.meanRelative, 2e-2)
                << hard.name << ", refinement " << refinement << ": max " << e.maxRelative;
            std::printf("%s, refinement %g: mean %.2e\n", hard.name, refinement, e.meanRelative);
        }
    }
}
