// The plugin API on the device: bad descriptions are refused before anything is recorded and leave
// the engine's images as they were; only the nodes a frame needs are built.
#include <cmath>
#include <limits>

#include "plugin_fixture.h"

using namespace plugin_test;
using lightscatter::Method;

namespace {

FrameSpec spotFrame() {
    FrameSpec s;
    s.screen = {24, 16};
    s.view = defaultView(s.screen);
    s.light = spotOverGrille();
    s.medium = fog();
    return s;
}

bool hasPass(const std::vector<std::string>& passes, const std::string& fragment) {
    for (const auto& p : passes)
        if (p.find(fragment) != std::string::npos) return true;
    return false;
}

}  // namespace

class PluginApiGpu : public PluginGpuTest {
protected:
    // Expects `change` to make the frame invalid with a message naming `field`, and the engine's
    // color to be untouched by the refused call.
    void expectRefused(const std::function<void(lightscatter::FrameDescription&)>& change,
                       const std::string& field) {
        TestFrame frame(dev(), spotFrame());
        const auto before = frame.color();
        auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                      smallSettings(frame.spec().screen));
        change(desc);
        try {
            plugin().render(desc);
            ADD_FAILURE() << "accepted; expected a refusal naming " << field;
        } catch (const lightscatter::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        }
        EXPECT_EQ(frame.color(), before) << field;
    }
};

TEST_F(PluginApiGpu, ZeroSlicesAreRefused) {
    expectRefused([](auto& d) { d.custom.slices = 0; }, "custom.slices");
}

TEST_F(PluginApiGpu, SlicesNotAMultipleOfFourAreRefused) {
    expectRefused([](auto& d) { d.custom.slices = 30; }, "multiple of 4");
}

TEST_F(PluginApiGpu, InitialStepMustBeAPowerOfTwo) {
    expectRefused([](auto& d) { d.custom.initialSampleStep = 12; }, "custom.initialSampleStep");
}

// Seed 004's simplified light model: I / (a1 r^2 + a0) needs a1 > 0 and a0 >= 0, both finite.
TEST_F(PluginApiGpu, BadSimplifiedModelCoefficientsAreRefused) {
    const float nan = std::numeric_limits<float>::quiet_NaN(),
                inf = std::numeric_limits<float>::infinity();
    for (float a1 : {0.0f, -1.0f, nan, inf})
        expectRefused([a1](auto& d) { d.custom.simplifiedA1 = a1; }, "custom.simplifiedA1");
    for (float a0 : {-0.01f, nan, inf})
        expectRefused([a0](auto& d) { d.custom.simplifiedA0 = a0; }, "custom.simplifiedA0");
    expectRefused([](auto& d) { d.custom.lightModel = static_cast<lightscatter::LightModel>(7); },
                  "custom.lightModel");
}

TEST_F(PluginApiGpu, DepthThatIsNotADepthFormatIsRefused) {
    expectRefused([](auto& d) { d.depth.format = VK_FORMAT_R8G8B8A8_UNORM; }, "depth.format R8G8B8A8_UNORM");
}

TEST_F(PluginApiGpu, ShadowMapOfTheWrongSizeIsRefused) {
    expectRefused([](auto& d) { d.light.shadowMapSize = 256; }, "does not match light.shadowMapSize 256");
}

TEST_F(PluginApiGpu, NaNInAMatrixIsRefused) {
    expectRefused([](auto& d) { d.camera.view[5] = std::numeric_limits<float>::quiet_NaN(); },
                  "camera.view element 5");
    expectRefused([](auto& d) { d.light.shadowViewProjection[0] = std::numeric_limits<float>::infinity(); },
                  "light.shadowViewProjection");
}

TEST_F(PluginApiGpu, MissingFinalLayoutIsRefused) {
    expectRefused([](auto& d) { d.color.finalLayout = VK_IMAGE_LAYOUT_UNDEFINED; }, "color.finalLayout");
}

TEST_F(PluginApiGpu, ColorMustBeLinearHdr) {
    expectRefused([](auto& d) { d.color.format = VK_FORMAT_R8G8B8A8_UNORM; }, "color.format");
}

TEST_F(PluginApiGpu, PointLightsTakeNoShadowMap) {
    expectRefused([](auto& d) { d.light.type = lightscatter::LightType::Point; }, "point lights are unshadowed");
}

TEST_F(PluginApiGpu, MediumAndLightRangesAreChecked) {
    expectRefused([](auto& d) { d.medium.g = 1.0f; }, "medium.g");
    expectRefused([](auto& d) { d.medium.betaM[1] = -1.0f; }, "medium.betaM");
    expectRefused([](auto& d) { d.light.halfAngleDegrees = 95.0f; }, "light.halfAngleDegrees");
    expectRefused([](auto& d) { d.light.radius = 0.0f; }, "light.radius");
}

TEST_F(PluginApiGpu, OnlyTheNodesAFrameNeedsAreBuilt) {
    // Spot with a shadow map: the epipolar set, and the point-light table the first time.
    TestFrame spot(dev(), spotFrame());
    auto r = run(spot, Method::Epipolar);
    EXPECT_TRUE(hasPass(r.passNames, "min/max trees"));
    EXPECT_FALSE(hasPass(r.passNames, "light color"));
    // The table is refilled only when the medium changes.
    r = run(spot, Method::Epipolar);
    EXPECT_TRUE(r.setupPasses.empty());
    FrameSpec denser = spotFrame();
    denser.medium.betaM = {0.05f, 0.05f, 0.05f};
    TestFrame other(dev(), denser);
    r = run(other, Method::Epipolar);
    EXPECT_TRUE(hasPass(r.setupPasses, "point-light table"));

    // Directional: no table.
    FrameSpec sunSpec = spotFrame();
    sunSpec.light = sunThroughGrille();
    TestFrame sun(dev(), sunSpec);
    r = run(sun, Method::Epipolar);
    EXPECT_TRUE(r.setupPasses.empty());
    EXPECT_FALSE(hasPass(r.passNames, "table"));

    // Without a shadow map: no trees, no ray marching.
    FrameSpec open = spotFrame();
    open.shadowed = false;
    TestFrame unshadowed(dev(), open);
    r = run(unshadowed, Method::Epipolar);
    EXPECT_FALSE(hasPass(r.passNames, "min/max"));
    EXPECT_FALSE(hasPass(r.passNames, "ray march"));
    EXPECT_TRUE(hasPass(r.passNames, "unshadowed"));

    // A spot behind the camera, pointing away: nothing but the extinction of the composite.
    FrameSpec away = spotFrame();
    away.light.position = {0.0f, 2.5f, 12.0f};
    away.light.direction = {0.0f, 0.0f, 1.0f};
    away.light.range = 5.0f;
    TestFrame missed(dev(), away);
    r = run(missed, Method::Epipolar);
    EXPECT_EQ(r.passNames,
              (std::vector<std::string>{"upload frame constants", "reconstruct camera-space z", "composite"}));
    const auto lin = missed.inscatter();
    for (float v : lin) EXPECT_TRUE(v == 0.0f || v == 1.0f);
}

TEST_F(PluginApiGpu, GraphIsReusedUntilItsShapeChanges) {
    TestFrame frame(dev(), spotFrame());
    run(frame, Method::Epipolar);
    const std::string first = plugin().graphJson();
    auto settings = smallSettings(frame.spec().screen);
    settings.refinementThreshold = 0.2f;  // a constant, not a shape
    run(frame, Method::Epipolar, settings);
    EXPECT_EQ(plugin().graphJson(), first);
    settings.slices += 4;  // a texture size: a new graph
    run(frame, Method::Epipolar, settings);
    EXPECT_NE(plugin().graphJson(), first);
    EXPECT_NE(plugin().graphDot().find("digraph"), std::string::npos);
}
