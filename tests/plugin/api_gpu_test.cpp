// The plugin API on the device: bad descriptions are refused before anything is recorded and leave
// the engine's images as they were; only the nodes a frame needs are built.
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <utility>

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

// A point light's six faces at `p` as lightscatter.h documents them (Vulkan's order and
// orientation): GL-style 90-degree perspectives with the classic cube cameras' up vectors.
std::array<lightscatter::Mat4, 6> cubeFaces(const lightscatter::Vec3& p) {
    const glm::vec3 L(p[0], p[1], p[2]);
    const glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(90.0f), 1.0f, 0.05f, 50.0f);
    const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                              {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    std::array<lightscatter::Mat4, 6> faces;
    for (size_t i = 0; i < 6; ++i) {
        const glm::mat4 m = projection * glm::lookAtRH(L, L + axes[i], ups[i]);
        std::memcpy(faces[i].data(), glm::value_ptr(m), sizeof(faces[i]));
    }
    return faces;
}

lightscatter::Mat4 times(const glm::mat4& left, const lightscatter::Mat4& m) {
    const glm::mat4 r = left * glm::make_mat4(m.data());
    lightscatter::Mat4 out;
    std::memcpy(out.data(), glm::value_ptr(r), sizeof(out));
    return out;
}

bool anyPassContains(const std::vector<std::string>& passes, const std::string& fragment) {
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
        // check() refuses what render() refuses, in the same words.
        std::string checked = "(accepted)";
        try {
            plugin().check(desc);
        } catch (const lightscatter::InvalidInput& e) {
            checked = e.what();
        }
        try {
            plugin().render(desc);
            ADD_FAILURE() << "accepted; expected a refusal naming " << field;
        } catch (const lightscatter::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
            EXPECT_EQ(checked, e.what());
        }
        EXPECT_EQ(frame.color(), before) << field;
    }
};

// Occluders are checked only by the methods that read them (issue #22: a scene of more than
// kMaxOccluders parts could not be rendered by any method).
TEST_F(PluginApiGpu, OnlyTheBeamTreeMethodsCheckTheOccluders) {
    TestFrame frame(dev(), spotFrame());
    auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                  smallSettings(frame.spec().screen));
    desc.occluders.resize(lightscatter::kMaxOccluders + 1);
    desc.occluders[3].outer.halfExtents = {0.5f, -1.0f, 0.5f};
    for (Method m : {Method::Epipolar, Method::BruteForce, Method::ConeMarch}) {
        desc.method = m;
        EXPECT_NO_THROW(plugin().render(desc)) << lightscatter::methodName(m);
    }
    for (Method m : {Method::BeamTreeAnalytic, Method::BeamTreeSampling}) {
        desc.method = m;
        try {
            plugin().check(desc);
            ADD_FAILURE() << lightscatter::methodName(m) << " took 4097 occluders";
        } catch (const lightscatter::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find("occluders has 4097 entries: at most 4096"),
                      std::string::npos)
                << e.what();
        }
    }
    desc.occluders.resize(8);
    try {
        plugin().check(desc);
        ADD_FAILURE() << "a box with a negative extent was taken";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("occluders[3]"), std::string::npos) << e.what();
    }
}

// The list of lights has a stated limit (issue #22: 10,000 unshadowed spots exhausted the
// machine, 2 MiB of table and 15 ms of setup each).
TEST_F(PluginApiGpu, MoreLightsThanTheLimitAreRefused) {
    TestFrame frame(dev(), spotFrame());
    auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                  smallSettings(frame.spec().screen));
    lightscatter::Light spot = desc.light;
    spot.shadowMapSize = 0;
    spot.shadowViewProjection = {};
    desc.light = {};
    desc.shadowMap.reset();
    desc.lights.assign(lightscatter::kMaxLights, {spot, std::nullopt, std::nullopt});
    EXPECT_NO_THROW(plugin().check(desc));
    desc.lights.push_back({spot, std::nullopt, std::nullopt});
    try {
        plugin().check(desc);
        ADD_FAILURE() << "65 lights taken";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("lights holds 65 lights: at most 64"),
                  std::string::npos)
            << e.what();
    }
}

// Plugin::check: what record() would refuse, found without recording or building anything; a
// method that cannot take the frame's lights included (the benchmark checks every run with it).
TEST_F(PluginApiGpu, CheckRefusesWhatRecordRefusesAndBuildsNothing) {
    TestFrame frame(dev(), spotFrame());
    auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                  smallSettings(frame.spec().screen));
    const rg::Device& d = dev();
    lightscatter::Plugin fresh({d.instance(), d.physical(), d.device(), d.queue(), d.queueFamily(),
                                &d.enabledFeatures(), d.instanceApiVersion()});
    EXPECT_NO_THROW(fresh.check(desc));
    EXPECT_EQ(fresh.report().frame, 0u);
    EXPECT_EQ(fresh.graphDot(), "");
    desc.lights = {{desc.light, desc.shadowMap, std::nullopt},
                   {desc.light, desc.shadowMap, std::nullopt}};
    desc.light = {};
    desc.shadowMap.reset();
    EXPECT_NO_THROW(plugin().check(desc));
    desc.method = Method::Analytic;
    try {
        fresh.check(desc);
        ADD_FAILURE() << "analytic accepted two shadowed lights";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("lights[0]: method analytic cannot cast shadows"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_EQ(fresh.report().frame, 0u);
}

TEST_F(PluginApiGpu, ZeroSlicesAreRefused) {
    expectRefused([](auto& d) { d.custom.epipolar.slices = 0; }, "custom.epipolar.slices");
}

TEST_F(PluginApiGpu, SlicesNotAMultipleOfFourAreRefused) {
    expectRefused([](auto& d) { d.custom.epipolar.slices = 30; }, "multiple of 4");
}

TEST_F(PluginApiGpu, InitialStepMustBeAPowerOfTwo) {
    expectRefused([](auto& d) { d.custom.epipolar.initialSampleStep = 12; },
                  "custom.epipolar.initialSampleStep");
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
    expectRefused([](auto& d) { d.depth.format = VK_FORMAT_R8G8B8A8_UNORM; },
                  "depth.format R8G8B8A8_UNORM");
}

TEST_F(PluginApiGpu, ShadowMapOfTheWrongSizeIsRefused) {
    expectRefused([](auto& d) { d.light.shadowMapSize = 256; },
                  "does not match light.shadowMapSize 256");
}

TEST_F(PluginApiGpu, NaNInAMatrixIsRefused) {
    expectRefused([](auto& d) { d.camera.view[5] = std::numeric_limits<float>::quiet_NaN(); },
                  "camera.view element 5");
    expectRefused(
        [](auto& d) { d.light.shadowViewProjection[0] = std::numeric_limits<float>::infinity(); },
        "light.shadowViewProjection");
}

TEST_F(PluginApiGpu, MissingFinalLayoutIsRefused) {
    expectRefused([](auto& d) { d.color.finalLayout = VK_IMAGE_LAYOUT_UNDEFINED; },
                  "color.finalLayout");
}

// The color is a storage image of a float format the shaders write in place, or a color attachment
// of a format the device blends into (composite_gpu_test.cpp renders them); without one, the
// engine composites itself from both outputs.
TEST_F(PluginApiGpu, TheColorIsAStorageFloatImageOrABlendableAttachment) {
    expectRefused([](auto& d) { d.color.format = VK_FORMAT_R8G8B8A8_UNORM; },
                  "color.usage lacks COLOR_ATTACHMENT: the plugin blends into a R8G8B8A8_UNORM "
                  "color as an attachment");
    expectRefused(
        [](auto& d) {
            d.color.format = VK_FORMAT_R8G8B8A8_UINT;  // integer: no blending
            d.color.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
            d.color.layout = d.color.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        },
        "color.format R8G8B8A8_UINT: this device cannot blend into it as a color attachment");
    expectRefused([](auto& d) { d.color.format = VK_FORMAT_UNDEFINED; },
                  "color.format is UNDEFINED (no color: the engine composites itself) and "
                  "transmittanceOut is not given");
    expectRefused(
        [](auto& d) {
            d.transmittanceOut = d.color;
            d.transmittanceOut->format = VK_FORMAT_R16G16_SFLOAT;
        },
        "transmittanceOut.format R16G16_SFLOAT: must be R16G16B16A16_SFLOAT or "
        "R32G32B32A32_SFLOAT");
    expectRefused(
        [](auto& d) {
            d.transmittanceOut = d.color;
            d.transmittanceOut->extent.width -= 1;
        },
        "transmittanceOut.extent");
}

// A point light's shadow map is a cube: six layers and six face matrices in Vulkan's order and
// orientation; each rule broken is refused naming the field (the frame's image has one layer).
TEST_F(PluginApiGpu, PointLightShadowMapsAreCheckedAsCubes) {
    using lightscatter::LightType;
    auto point = [](lightscatter::FrameDescription& d) {
        d.light.type = LightType::Point;
        d.light.cubeFaceViewProjections = cubeFaces(d.light.position);
    };
    expectRefused([](auto& d) { d.light.type = LightType::Point; },
                  "light.cubeFaceViewProjections[0] is singular");
    expectRefused(point, "shadowMap.arrayLayers = 1: must be 6");
    expectRefused(
        [&](auto& d) {
            point(d);
            std::swap(d.light.cubeFaceViewProjections[2], d.light.cubeFaceViewProjections[3]);
        },
        "light.cubeFaceViewProjections[2] puts the point 1 m along +Y");
    expectRefused(
        [&](auto& d) {  // 100 degrees wide instead of 90
            point(d);
            const float s = 1.0f / std::tan(glm::radians(50.0f));
            d.light.cubeFaceViewProjections[4] =
                times(glm::scale(glm::mat4(1.0f), glm::vec3(s, s, 1.0f)),
                      d.light.cubeFaceViewProjections[4]);
        },
        "light.cubeFaceViewProjections[4] is not face +Z");
    expectRefused(
        [&](auto& d) {  // mirrored: clip x flipped
            point(d);
            d.light.cubeFaceViewProjections[1] =
                times(glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)),
                      d.light.cubeFaceViewProjections[1]);
        },
        "light.cubeFaceViewProjections[1] is not face -X");
    expectRefused(
        [&](auto& d) {  // the apex 10 cm off the light
            point(d);
            auto p = d.light.position;
            p[1] += 0.1f;
            d.light.cubeFaceViewProjections[5] = cubeFaces(p)[5];
        },
        "light.cubeFaceViewProjections[5] does not look along -Z");
    expectRefused(
        [&](auto& d) {
            point(d);
            d.light.shadowReversedZ = true;
        },
        "light.cubeFaceViewProjections[0] puts depth");
    expectRefused(
        [&](auto& d) {
            point(d);
            d.light.cubeFaceViewProjections[3][7] = std::numeric_limits<float>::quiet_NaN();
        },
        "light.cubeFaceViewProjections[3] element 7");
    // Layers elsewhere: a spot's map and the other images have one.
    expectRefused([](auto& d) { d.shadowMap->arrayLayers = 6; },
                  "shadowMap.arrayLayers = 6: must be 1");
    expectRefused([](auto& d) { d.depth.arrayLayers = 2; }, "depth.arrayLayers");
}

TEST_F(PluginApiGpu, MediumAndLightRangesAreChecked) {
    expectRefused([](auto& d) { d.medium.g = 1.0f; }, "medium.g");
    expectRefused([](auto& d) { d.medium.betaM[1] = -1.0f; }, "medium.betaM");
    expectRefused([](auto& d) { d.light.outerConeAngleDegrees = 95.0f; },
                  "light.outerConeAngleDegrees");
    expectRefused(
        [](auto& d) {
            d.light.innerConeAngleDegrees = 40.0f;
            d.light.outerConeAngleDegrees = 30.0f;
        },
        "light.innerConeAngleDegrees = 40: must be at most outerConeAngleDegrees");
    expectRefused([](auto& d) { d.light.radius = 0.0f; }, "light.radius");
}

TEST_F(PluginApiGpu, OnlyTheNodesAFrameNeedsAreBuilt) {
    // Spot with a shadow map: the epipolar set, and the point-light table the first time.
    TestFrame spot(dev(), spotFrame());
    auto r = run(spot, Method::Epipolar);
    EXPECT_TRUE(anyPassContains(r.passNames, "min/max trees"));
    EXPECT_FALSE(anyPassContains(r.passNames, "light color"));
    // The table is refilled only when the medium changes.
    r = run(spot, Method::Epipolar);
    EXPECT_TRUE(r.setupPasses.empty());
    FrameSpec denser = spotFrame();
    denser.medium.betaM = {0.05f, 0.05f, 0.05f};
    TestFrame other(dev(), denser);
    r = run(other, Method::Epipolar);
    EXPECT_TRUE(anyPassContains(r.setupPasses, "point-light table"));

    // Directional: no table.
    FrameSpec sunSpec = spotFrame();
    sunSpec.light = sunThroughGrille();
    TestFrame sun(dev(), sunSpec);
    r = run(sun, Method::Epipolar);
    EXPECT_TRUE(r.setupPasses.empty());
    EXPECT_FALSE(anyPassContains(r.passNames, "table"));

    // Without a shadow map: no trees, no ray marching.
    FrameSpec open = spotFrame();
    open.shadowed = false;
    TestFrame unshadowed(dev(), open);
    r = run(unshadowed, Method::Epipolar);
    EXPECT_FALSE(anyPassContains(r.passNames, "min/max"));
    EXPECT_FALSE(anyPassContains(r.passNames, "ray march"));
    EXPECT_TRUE(anyPassContains(r.passNames, "unshadowed"));

    // A spot behind the camera, pointing away: nothing but the extinction of the composite.
    FrameSpec away = spotFrame();
    away.light.position = {0.0f, 2.5f, 12.0f};
    away.light.direction = {0.0f, 0.0f, 1.0f};
    away.light.range = 5.0f;
    TestFrame missed(dev(), away);
    r = run(missed, Method::Epipolar);
    EXPECT_EQ(r.passNames, (std::vector<std::string>{"upload frame constants", "composite"}));
    const auto lin = missed.inscatter();
    for (float v : lin) EXPECT_TRUE(v == 0.0f || v == 1.0f);
}

TEST_F(PluginApiGpu, GraphIsReusedUntilItsShapeChanges) {
    TestFrame frame(dev(), spotFrame());
    run(frame, Method::Epipolar);
    const std::string first = plugin().graphJson();
    auto settings = smallSettings(frame.spec().screen);
    settings.epipolar.refinementThreshold = 0.2f;  // a constant, not a shape
    run(frame, Method::Epipolar, settings);
    EXPECT_EQ(plugin().graphJson(), first);
    settings.epipolar.slices += 4;  // a texture size: a new graph
    run(frame, Method::Epipolar, settings);
    EXPECT_NE(plugin().graphJson(), first);
    EXPECT_NE(plugin().graphDot().find("digraph"), std::string::npos);
}
