// Every method's graph with its transients poisoned at first use (NaN, all ones): the output must
// be free of NaN and equal to the unpoisoned one, which shows that no pass reads memory that
// another resource (or the previous frame) left behind. The rendergraph test shows the poison is
// real.
#include <cmath>
#include <string>

#include "plugin_fixture.h"

using namespace plugin_test;
using lightscatter::Method;

namespace {

struct PoisonCase {
    std::string name;
    lightscatter::Light light;
    Method method;
    void (*tweak)(lightscatter::Settings&) = nullptr;
    bool coloredLight = false;
    bool shadowed = true;
    glm::vec3 eye{0.0f, 2.5f, 9.0f};
    // Counts the march's steps and asserts the march list carried samples (its march stores
    // where its samples live, and leaves the other texels as the poison left them).
    bool marchList = false;
};

std::vector<PoisonCase> poisonCases() {
    lightscatter::Light point = spotOverGrille();
    point.type = lightscatter::LightType::Point;
    lightscatter::Light sunAhead = sunThroughGrille();
    sunAhead.direction = {0.1f, -0.3f, 1.0f};  // on the screen: every slice, the march list
    return {
        {"spot epipolar", spotOverGrille(), Method::Epipolar},
        {"spot epipolar without trees", spotOverGrille(), Method::Epipolar,
         [](lightscatter::Settings& s) { s.epipolar.minMaxTrees = false; }},
        {"spot epipolar interpolating Lin", spotOverGrille(), Method::Epipolar,
         [](lightscatter::Settings& s) {
             s.epipolar.interpolation = lightscatter::Interpolation::Inscattering;
         }},
        {"spot epipolar without fix-up", spotOverGrille(), Method::Epipolar,
         [](lightscatter::Settings& s) { s.epipolar.fixup = false; }},
        {"spot brute force", spotOverGrille(), Method::BruteForce},
        {"colored spot epipolar", spotOverGrille(), Method::Epipolar, nullptr, true},
        {"directional epipolar", sunThroughGrille(), Method::Epipolar},
        {"directional brute force", sunThroughGrille(), Method::BruteForce},
        {"sun on the screen epipolar, the march list",
         sunAhead,
         Method::Epipolar,
         [](lightscatter::Settings& s) { s.epipolar.refinementThreshold = 0.3f; },
         false,
         true,
         {0.0f, 2.5f, 9.0f},
         true},
        {"point closed form", point, Method::Epipolar, nullptr, false, false},
        {"spot behind the camera",
         spotOverGrille(),
         Method::Epipolar,
         nullptr,
         false,
         true,
         {0.0f, 2.5f, -9.0f}},
    };
}

}  // namespace

class PoisonedTransientsGpu : public PluginGpuTest {};

TEST_F(PoisonedTransientsGpu, EveryMethodGivesTheSameImageWithoutNaN) {
    for (const PoisonCase& c : poisonCases()) {
        FrameSpec spec;
        spec.screen = {48, 32};
        spec.view = lookAt(c.eye, {0.0f, 1.5f, 0.0f}, 60.0f, 1.5f, 0.1f, 50.0f);
        spec.light = c.light;
        spec.medium = fog();
        spec.coloredLight = c.coloredLight;
        spec.shadowed = c.shadowed;
        TestFrame frame(dev(), spec);
        auto settings = smallSettings(spec.screen);
        if (c.tweak) c.tweak(settings);
        auto description = frame.description(c.method, lightscatter::Profile::Custom, settings);
        description.debug.countSteps = c.marchList;

        frame.resetColor();
        const lightscatter::FrameReport report = plugin().render(description);
        const auto clean = frame.inscatter();
        if (c.marchList) {
            ASSERT_TRUE(report.steps.has_value()) << c.name;
            EXPECT_GT(report.steps->listedSamples, 0u) << c.name;
        }
        description.debug.poisonTransients = true;
        for (int run = 0; run < 2; ++run) {  // the second frame reuses the poisoned graph
            frame.resetColor();
            plugin().render(description);
            ASSERT_NE(plugin().graphJson().find("\"poisonTransients\": true"), std::string::npos)
                << c.name;
            const auto poisoned = frame.inscatter();
            size_t nan = 0, differ = 0;
            for (size_t i = 0; i < poisoned.size(); ++i) {
                nan += std::isnan(poisoned[i]) ? 1 : 0;
                differ += poisoned[i] != clean[i] ? 1 : 0;
            }
            EXPECT_EQ(nan, 0u) << c.name;
            EXPECT_EQ(differ, 0u) << c.name;
            const auto color = frame.color();
            for (float v : color)
                ASSERT_FALSE(std::isnan(v)) << c.name << ": NaN in the composited color";
        }
    }
}
