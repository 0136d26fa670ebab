// shaftIntensity(): the intensity it gives a light renders the shaft brightness asked for, and what
// it cannot give is refused naming the goal's field.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "plugin_fixture.h"
#include "support/gpu_test.h"

namespace plugin_test {
namespace {

using lightscatter::LightType;

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

std::string refusal(LightType type, const lightscatter::Medium& m,
                    const lightscatter::ShaftGoal& goal) {
    try {
        lightscatter::shaftIntensity(type, m, goal);
    } catch (const lightscatter::InvalidInput& e) {
        return e.what();
    }
    return "(accepted)";
}

class ShaftUnitsGpu : public PluginGpuTest {};

// A camera looks level across a narrow spot's beam 10 m away, 5 m below the spot: the pixel at
// the centre of the screen sees the shaft the goal describes, and renders its brightness.
TEST_F(ShaftUnitsGpu, TheIntensityForABrightnessRendersThatBrightness) {
    constexpr VkExtent2D kShaftScreen{33, 33};  // odd: the centre pixel's ray is the view axis
    FrameSpec spec;
    spec.screen = kShaftScreen;
    spec.view = lookAt({0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, -10.0f}, 20.0f, 1.0f, 0.1f, 100.0f);
    spec.medium.betaR = {5.8e-6f, 13.5e-6f, 33.1e-6f};
    spec.medium.betaM = {0.01f, 0.01f, 0.01f};
    spec.medium.g = 0.76f;
    spec.medium.maxDistance = 60.0f;
    spec.shadowed = false;
    spec.depthOverride.assign(size_t{kShaftScreen.width} * kShaftScreen.height,
                              1.0f);  // sky everywhere
    lightscatter::Light& spot = spec.light;
    spot.type = LightType::Spot;
    spot.position = {0.0f, 6.0f, -10.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.innerConeAngleDegrees = spot.outerConeAngleDegrees = 5.0f;

    lightscatter::ShaftGoal goal;
    goal.brightness = 0.05f;
    goal.viewDistance = 10.0f;
    goal.lightDistance = 5.0f;
    goal.beamWidth = float(2.0 * 5.0 * std::tan(5.0 * 3.14159265358979 / 180.0));
    goal.scatteringAngleDegrees = 90.0f;
    goal.radius = spot.radius;
    spot.intensity = lightscatter::shaftIntensity(LightType::Spot, spec.medium, goal);
    // Rayleigh scatters more blue: the blue channel needs less.
    EXPECT_LT(spot.intensity[2], spot.intensity[0]);

    TestFrame frame(dev(), spec);
    // Brute force: docs/model.md's integral as it is (analytic would not do: it assumes isotropic
    // scattering and no extinction, 9 times this shaft's brightness here).
    plugin().render(frame.description(lightscatter::Method::BruteForce,
                                      lightscatter::Profile::Custom, smallSettings(kShaftScreen)));
    const std::vector<float> lin = frame.inscatter();
    const size_t centre =
        (size_t{kShaftScreen.height / 2} * kShaftScreen.width + kShaftScreen.width / 2) * 4;
    for (int c = 0; c < 3; ++c)
        // The irradiance across the beam is within 1% of the centre's: the goal's one value.
        EXPECT_NEAR(lin[centre + c], goal.brightness, 0.02 * goal.brightness) << "channel " << c;
}

TEST(ShaftUnits, WhatCannotBeGivenIsRefusedNamingTheField) {
    const lightscatter::Medium fog;
    lightscatter::ShaftGoal goal;
    goal.brightness = 0.0f;
    EXPECT_TRUE(contains(refusal(LightType::Spot, fog, goal),
                         "shaftIntensity: goal.brightness = 0: must be finite and > 0"));
    goal = {};
    goal.scatteringAngleDegrees = 181.0f;
    EXPECT_TRUE(contains(refusal(LightType::Spot, fog, goal),
                         "goal.scatteringAngleDegrees = 181: must be in [0, 180]"));
    goal = {};
    goal.lightDistance = 0.0f;  // a directional light has no distance to it
    EXPECT_TRUE(contains(refusal(LightType::Point, fog, goal), "goal.lightDistance = 0"));
    EXPECT_EQ(refusal(LightType::Directional, fog, goal), "(accepted)");
    lightscatter::Medium clear;
    clear.betaR = clear.betaM = {0.0f, 0.0f, 0.0f};
    EXPECT_TRUE(contains(refusal(LightType::Spot, clear, {}), "the medium scatters nothing"));
    lightscatter::Medium thick = fog;
    thick.betaM = {1.0f, 1.0f, 1.0f};  // exp(-15) on the way: more than kMaxIntensity
    goal = {};
    goal.viewDistance = 100.0f;
    EXPECT_TRUE(contains(refusal(LightType::Spot, thick, goal), "above limits::kMaxIntensity"));
}

}  // namespace
}  // namespace plugin_test
