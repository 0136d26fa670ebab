// The plugin API against hostile input (issue #42), the counterpart of the command line's
// CliHostile: each row turns a valid frame into one the plugin must refuse, and expects one line
// that names the fields and the rule. check() refuses it in the same words, the engine's images
// are untouched, and the valid frame renders afterwards. Any validation message fails the row
// (GpuTest): before these checks, several rows rendered wrong images or raised messages.
#include <cstring>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <string>
#include <vector>

#include "plugin_fixture.h"
#include "rendergraph/owned_image.h"

// A namespace of its own: the test files are compiled in batches (unity build), and their helpers'
// names (spotFrame, Row) repeat.
namespace api_hostile_test {
namespace {

using namespace plugin_test;
using lightscatter::FrameDescription;
using lightscatter::Method;

// Engine images a row hands in beside the frame's own.
struct Extra {
    // A color the plugin could also sample (STORAGE and SAMPLED), so that the refusal of its second
    // role cannot come from a missing usage.
    std::unique_ptr<TestImage> sampledColor;
    std::unique_ptr<TestImage> depthCookie;  // D32_SFLOAT, sampled
    std::unique_ptr<TestImage> uintCookie;   // R8G8B8A8_UINT: no linear filter
    std::unique_ptr<rg::OwnedImage> volume;  // 3D, froxels' grid of the frame
    // The frame's shadow map, resting in GENERAL.
    std::unique_ptr<TestImage> generalShadowMap;
};

struct Row {
    const char* name;
    std::function<void(FrameDescription&, Extra&)> change;
    std::vector<std::string> words;  // each in the refusal
    std::string absent = "";         // never in it (a field the refusal must not blame)
};

FrameSpec hostileSpotFrame() {
    FrameSpec s;
    s.screen = {24, 16};
    s.view = defaultView(s.screen);
    s.light = spotOverGrille();
    s.medium = fog();
    return s;
}

// The frame's one light as a list of one.
void asList(FrameDescription& d) {
    d.lights = {{d.light, d.shadowMap, d.lightColor}};
    d.light = {};
    d.shadowMap.reset();
    d.lightColor.reset();
}

void useSampledColor(FrameDescription& d, Extra& e) {
    d.color = e.sampledColor->input();
}

void froxelVolumeOut(FrameDescription& d, Extra& e) {
    d.method = Method::Froxels;
    const lightscatter::FroxelVolume grid = lightscatter::froxelVolume(d);
    e.volume = std::make_unique<rg::OwnedImage>(
        testing_support::device(), VK_FORMAT_R16G16B16A16_SFLOAT,
        VkExtent2D{grid.width, grid.height}, VK_IMAGE_USAGE_STORAGE_BIT, "hostile volumeOut", 1, 0,
        grid.depth);
    lightscatter::ImageInput v;
    v.image = e.volume->image();
    v.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    v.extent = {grid.width, grid.height};
    v.depth = grid.depth;
    v.usage = VK_IMAGE_USAGE_STORAGE_BIT;
    v.finalLayout = VK_IMAGE_LAYOUT_GENERAL;
    d.volumeOut = v;
}

bool sameBytes(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

template <class Enum>
Enum bad(int value) {
    return static_cast<Enum>(value);
}

// Vulkan's orthographic projection (clip y down): parallel rays, w = 1 everywhere.
lightscatter::Mat4 orthographic() {
    glm::mat4 p = glm::orthoRH_ZO(-4.0f, 4.0f, -3.0f, 3.0f, 0.1f, 50.0f);
    p[1][1] = -p[1][1];
    return toMat4(p);
}

const std::vector<Row>& rows() {
    static const std::vector<Row> kRows = {
        // One image in two roles, one of them written.
        {"ColorAsInscatterOut",
         [](auto& d, auto&) { d.inscatterOut = d.color; },
         {"color.image and inscatterOut.image are one VkImage",
          "the plugin writes color and inscatterOut"}},
        {"ColorAsLightColor",
         [](auto& d, auto& e) {
             useSampledColor(d, e);
             d.lightColor = d.color;
         },
         {"color.image and lightColor.image are one VkImage", "the plugin writes color"}},
        {"ColorAsALightsLightColor",
         [](auto& d, auto& e) {
             useSampledColor(d, e);
             asList(d);
             d.lights[0].lightColor = d.color;
         },
         {"color.image and lights[0].lightColor.image are one VkImage"}},
        {"ColorAsVolumeOut",
         [](auto& d, auto& e) {
             froxelVolumeOut(d, e);
             d.color.image = d.volumeOut->image;
         },
         {"color.image and volumeOut.image are one VkImage",
          "the plugin writes color and volumeOut"}},
        {"InscatterOutAsTransmittanceOut",
         [](auto& d, auto&) { d.transmittanceOut = d.inscatterOut; },
         {"inscatterOut.image and transmittanceOut.image are one VkImage"}},
        {"ColorAsNoise",
         [](auto& d, auto& e) {
             useSampledColor(d, e);
             d.noise = d.color;
         },
         {"color.image and noise.image are one VkImage"}},
        // One image read in two roles, in two layouts.
        {"DepthAsShadowMapInAnotherLayout",
         [](auto& d, auto&) {
             d.shadowMap->image = d.depth.image;
             d.depth.layout = d.depth.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
         },
         {"depth.image and shadowMap.image are one VkImage in two layouts",
          "depth.layout DEPTH_STENCIL_READ_ONLY_OPTIMAL",
          "shadowMap.layout SHADER_READ_ONLY_OPTIMAL"}},
        {"OneShadowMapTwoFinalLayouts",
         [](auto& d, auto&) {
             asList(d);
             d.lights.push_back(d.lights[0]);
             d.lights[1].shadowMap->finalLayout = VK_IMAGE_LAYOUT_GENERAL;
         },
         {"lights[0].shadowMap.image and lights[1].shadowMap.image are one VkImage in two layouts",
          "lights[1].shadowMap.finalLayout GENERAL"}},
        {"OneShadowMapInGeneralForTwoLights",
         [](auto& d, auto& e) {
             d.shadowMap = e.generalShadowMap->input();
             asList(d);
             d.lights.push_back(d.lights[0]);
         },
         {"lights[0].shadowMap.image and lights[1].shadowMap.image are one VkImage in GENERAL",
          "must be in SHADER_READ_ONLY_OPTIMAL"}},
        {"DepthAsShadowMapInOneLayout",
         [](auto& d, auto&) { d.shadowMap->image = d.depth.image; },
         {"depth.image and shadowMap.image are one VkImage",
          "the depth may be depth-tested in DEPTH_STENCIL_READ_ONLY_OPTIMAL"}},
        // Formats a role's sampler cannot take.
        {"DepthFormatAsLightColor",
         [](auto& d, auto& e) { d.lightColor = e.depthCookie->input(); },
         {"lightColor.format D32_SFLOAT is a depth/stencil format", "must be a color format"}},
        {"UnfilterableLightColor",
         [](auto& d, auto& e) { d.lightColor = e.uintCookie->input(); },
         {"lightColor.format R8G8B8A8_UINT", "linear filter", "SAMPLED_IMAGE_FILTER_LINEAR"}},
        {"UnfilterableNoise",
         [](auto& d, auto& e) { d.noise = e.uintCookie->input(); },
         {"noise.format R8G8B8A8_UINT", "SAMPLED_IMAGE_FILTER_LINEAR"}},
        // Enums out of range, each where it enters.
        {"Profile99",
         [](auto& d, auto&) { d.profile = bad<lightscatter::Profile>(99); },
         {"profile = 99: not a Profile value", "custom"}},
        {"FrameMethod42",
         [](auto& d, auto&) { d.method = bad<Method>(42); },
         {"method = 42: not a Method value", "epipolar"},
         "lights[0]"},
        {"LightsMethod42",
         [](auto& d, auto&) {
             asList(d);
             d.lights[0].method = bad<Method>(42);
         },
         {"lights[0].method = 42: not a Method value"}},
        {"LightType7",
         [](auto& d, auto&) { d.light.type = bad<lightscatter::LightType>(7); },
         {"light.type = 7: not a LightType value"}},
        {"ListLightType7",
         [](auto& d, auto&) {
             asList(d);
             d.lights[0].light.type = bad<lightscatter::LightType>(7);
         },
         {"lights[0].light.type = 7: not a LightType value"}},
        {"RangeFalloff5",
         [](auto& d, auto&) { d.light.rangeFalloff = bad<lightscatter::RangeFalloff>(5); },
         {"light.rangeFalloff = 5: not a RangeFalloff value"}},
        {"MiePhase9",
         [](auto& d, auto&) { d.medium.phase = bad<lightscatter::MiePhase>(9); },
         {"medium.phase = 9: not a MiePhase value"}},
        {"ShadowFilter3",
         [](auto& d, auto&) { d.custom.shadowFilter = bad<lightscatter::ShadowFilter>(3); },
         {"custom.shadowFilter = 3", "nearest, bilinear"}},
        {"LightModel7",
         [](auto& d, auto&) { d.custom.lightModel = bad<lightscatter::LightModel>(7); },
         {"custom.lightModel = 7"}},
        {"Interpolation4",
         [](auto& d, auto&) {
             d.custom.epipolar.interpolation = bad<lightscatter::Interpolation>(4);
         },
         {"custom.epipolar.interpolation = 4"}},
        {"PlaneTarget9",
         [](auto& d, auto&) { d.custom.planes.target = bad<lightscatter::PlaneTarget>(9); },
         {"custom.planes.target = 9"}},
        {"LightsOwnShadowFilter3",
         [](auto& d, auto&) {
             asList(d);
             d.lights[0].settings = d.custom;
             d.lights[0].settings->shadowFilter = bad<lightscatter::ShadowFilter>(3);
         },
         {"lights[0].settings.shadowFilter = 3"}},
        // The camera.
        {"OrthographicProjection",
         [](auto& d, auto&) { d.camera.projection = orthographic(); },
         {"camera.projection is not a perspective projection", "(0, 0, 0, 1)",
          "an orthographic projection's"}},
    };
    return kRows;
}

class PluginApiHostile : public PluginGpuTest, public ::testing::WithParamInterface<Row> {};

TEST_P(PluginApiHostile, IsRefusedInOneLineAndTheValidFrameStillRenders) {
    const Row& row = GetParam();
    TestFrame frame(dev(), hostileSpotFrame());
    Extra extra;
    extra.sampledColor =
        std::make_unique<TestImage>(dev(), VK_FORMAT_R32G32B32A32_SFLOAT, frame.spec().screen,
                                    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                    VK_IMAGE_LAYOUT_GENERAL, "hostile sampled color");
    extra.depthCookie = std::make_unique<TestImage>(
        dev(), VK_FORMAT_D32_SFLOAT, VkExtent2D{32, 32}, VK_IMAGE_USAGE_SAMPLED_BIT,
        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "hostile D32 cookie");
    extra.uintCookie = std::make_unique<TestImage>(
        dev(), VK_FORMAT_R8G8B8A8_UINT, VkExtent2D{32, 32}, VK_IMAGE_USAGE_SAMPLED_BIT,
        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "hostile uint cookie");
    const uint32_t n = frame.light().shadowMapSize;
    const FrameSpec& spec = frame.spec();
    extra.generalShadowMap = std::make_unique<TestImage>(
        dev(), VK_FORMAT_D32_SFLOAT, VkExtent2D{n, n}, VK_IMAGE_USAGE_SAMPLED_BIT,
        VK_IMAGE_LAYOUT_GENERAL, "hostile shadow map in GENERAL");
    extra.generalShadowMap->upload(renderShadowMap(
        spec.scene, spotShadowMatrix(frame.light(), spec.shadowNear, spec.shadowFar), n));
    const auto valid = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                         smallSettings(frame.spec().screen));
    auto hostile = valid;
    row.change(hostile, extra);
    const auto color = frame.color();
    const auto lin = frame.inscatter();

    std::string checked = "(accepted)";
    try {
        plugin().check(hostile);
    } catch (const lightscatter::InvalidInput& e) {
        checked = e.what();
    }
    std::string rendered = "(accepted)";
    try {
        plugin().render(hostile);
    } catch (const lightscatter::InvalidInput& e) {
        rendered = e.what();
    }
    EXPECT_EQ(checked, rendered);
    EXPECT_EQ(rendered.find('\n'), std::string::npos) << rendered;
    for (const std::string& w : row.words)
        EXPECT_NE(rendered.find(w), std::string::npos) << "no \"" << w << "\" in: " << rendered;
    if (!row.absent.empty()) {
        EXPECT_EQ(rendered.find(row.absent), std::string::npos) << rendered;
    }
    // Bytes: what the engine left in the output may hold NaNs.
    EXPECT_TRUE(sameBytes(frame.color(), color)) << "the refused frame wrote the color";
    EXPECT_TRUE(sameBytes(frame.inscatter(), lin)) << "the refused frame wrote inscatterOut";

    const lightscatter::FrameReport r = plugin().render(valid);
    EXPECT_EQ(r.method, "epipolar");
    EXPECT_NE(frame.color(), color) << "the valid frame composited nothing";
}

INSTANTIATE_TEST_SUITE_P(Rows, PluginApiHostile, ::testing::ValuesIn(rows()),
                         [](const ::testing::TestParamInfo<Row>& row) {
                             return std::string(row.param.name);
                         });

class PluginApiSharedImage : public PluginGpuTest {};

// Sharing is not refused as such: lights that sample one shadow map in one layout render (the
// light-identity tests draw every light's shadows from one map).
TEST_F(PluginApiSharedImage, OneImageTwoRolesReadInOneLayoutIsAccepted) {
    TestFrame frame(dev(), hostileSpotFrame());
    auto d = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                               smallSettings(frame.spec().screen));
    asList(d);
    d.lights.push_back(d.lights[0]);
    EXPECT_NO_THROW(plugin().render(d));
}

}  // namespace
}  // namespace api_hostile_test
