// A light's shadow matrix checked against the light (issue #38: an engine's spot whose position
// was not its shadowViewProjection's apex rendered a white wedge and black air, and a cone wider
// than its frustum lit the air outside it unshadowed). Each mistake is refused naming the field,
// the measured value and the tolerance, leaving the engine's color as it was; the same frame
// without the mistake, or within the tolerance, renders.
#include <cmath>
#include <cstring>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <string>

#include "plugin_fixture.h"
#include "support/projection.h"

using namespace plugin_test;
using lightscatter::Method;

// Named rather than anonymous: the unity build puts this file beside others with helpers of the
// same names.
namespace lp {

FrameSpec spotFrame() {
    FrameSpec s;
    s.screen = {24, 16};
    s.view = defaultView(s.screen);
    s.light = spotOverGrille();  // at (0.3, 6, 0.2), its frustum 32 degrees each side, 0.5 to 30 m
    s.medium = fog();
    return s;
}

FrameSpec sunFrame() {
    FrameSpec s = spotFrame();
    s.light = sunThroughGrille();
    return s;
}

glm::vec3 vec(const lightscatter::Vec3& v) {
    return {v[0], v[1], v[2]};
}

lightscatter::Vec3 plugin3(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

// `d` turned by `degrees` about an axis across it.
lightscatter::Vec3 tilted(const lightscatter::Vec3& d, float degrees) {
    const glm::vec3 v = glm::normalize(vec(d));
    const glm::vec3 across = glm::normalize(glm::cross(v, glm::vec3(1.0f, 0.0f, 0.0f)));
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), across);
    return plugin3(glm::vec3(turn * glm::vec4(v, 0.0f)));
}

lightscatter::Vec3 moved(lightscatter::Vec3 p, float dx, float dy, float dz) {
    p[0] += dx;
    p[1] += dy;
    p[2] += dz;
    return p;
}

// The classic 90-degree cube cameras at `p`, in Vulkan's layer order (lightscatter.h).
std::array<lightscatter::Mat4, 6> cubeFaces(const lightscatter::Vec3& p) {
    const glm::vec3 L = vec(p);
    const glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(90.0f), 1.0f, 0.05f, 50.0f);
    const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                              {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    std::array<lightscatter::Mat4, 6> faces;
    for (size_t i = 0; i < 6; ++i)
        faces[i] = toMat4(projection * glm::lookAtRH(L, L + axes[i], ups[i]));
    return faces;
}

// `d` with its single light given as lights = {another light of the same kind, it}: the light
// under test is lights[1].
lightscatter::FrameDescription asSecondLight(lightscatter::FrameDescription d) {
    lightscatter::LightInput first{d.light, d.shadowMap, d.lightColor};
    lightscatter::LightInput second = first;
    d.lights = {first, second};
    d.light = {};
    d.shadowMap.reset();
    d.lightColor.reset();
    return d;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace lp

class LightProjectionGpu : public PluginGpuTest {
  protected:
    using Change = std::function<void(lightscatter::FrameDescription&)>;

    // Renders `spec` with `change` made to its description: empty when it rendered, else the
    // refusal, checked to be one line that left the engine's color as it was.
    std::string outcome(const FrameSpec& spec, const Change& change) {
        TestFrame frame(dev(), spec);
        const auto before = frame.color();
        auto d = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                   smallSettings(frame.spec().screen));
        change(d);
        try {
            plugin().render(d);
        } catch (const lightscatter::InvalidInput& e) {
            const std::string m = e.what();
            EXPECT_EQ(m.find('\n'), std::string::npos) << "one line: " << m;
            EXPECT_EQ(frame.color(), before) << m;
            return m;
        }
        return {};
    }

    void expectRefused(const FrameSpec& spec, const Change& change,
                       std::initializer_list<const char*> parts) {
        const std::string m = outcome(spec, change);
        EXPECT_FALSE(m.empty()) << "accepted; expected a refusal saying " << *parts.begin();
        for (const char* part : parts) EXPECT_TRUE(lp::contains(m, part)) << m;
    }

    void expectRendered(const FrameSpec& spec, const Change& change, const std::string& what) {
        EXPECT_EQ(outcome(spec, change), "") << what;
    }
};

// The frame's spot is at its matrix's apex (0.3, 6, 0.2); its range, 20 m, is nearer than the
// matrix's far plane (30 m), so the apex may be 1e-3 of that, plus 1e-5 of the 6 m from the
// origin, away: 2.006 cm.
TEST_F(LightProjectionGpu, ASpotAwayFromItsMatrixApexIsRefused) {
    expectRendered(
        lp::spotFrame(), [](auto&) {}, "the spot at its apex");
    expectRendered(
        lp::spotFrame(),
        [](auto& d) { d.light.position = lp::moved(d.light.position, 0.01f, 0, 0); },
        "1 cm off the apex, within the tolerance");
    // A stale position (the light moved since its shadow map was drawn).
    expectRefused(
        lp::spotFrame(),
        [](auto& d) { d.light.position = lp::moved(d.light.position, 0.1f, 0, 0); },
        {"light.position is 0.1 m from the apex of light.shadowViewProjection, (0.3, 6, 0.2)",
         "must be within 0.02006 m (1e-3 of the light's reach, 20 m, its range, plus 1e-5 of its "
         "distance from the origin)"});
    // The position in another space: the camera's view space.
    expectRefused(lp::spotFrame(),
                  [](auto& d) {
                      const glm::mat4 view = glm::make_mat4(d.camera.view.data());
                      d.light.position =
                          lp::plugin3(glm::vec3(view * glm::vec4(lp::vec(d.light.position), 1.0f)));
                  },
                  {"light.position is", "from the apex of light.shadowViewProjection"});
    // A light of the list is named as the list names it.
    expectRefused(lp::spotFrame(),
                  [](auto& d) {
                      d = lp::asSecondLight(d);
                      d.lights[1].light.position =
                          lp::moved(d.lights[1].light.position, 0, -0.5f, 0);
                  },
                  {"lights[1]: lights[1].light.position is 0.5 m from the apex of "
                   "lights[1].light.shadowViewProjection"});
    expectRendered(
        lp::spotFrame(), [](auto& d) { d = lp::asSecondLight(d); }, "the list of two spots");
}

TEST_F(LightProjectionGpu, ASpotLookingOffItsFrustumAxisIsRefused) {
    expectRendered(
        lp::spotFrame(), [](auto& d) { d.light.direction = lp::tilted(d.light.direction, 0.05f); },
        "0.05 degrees off the axis, within the tolerance");
    expectRefused(
        lp::spotFrame(), [](auto& d) { d.light.direction = lp::tilted(d.light.direction, 1.0f); },
        {"light.direction is ", " degrees off the axis of light.shadowViewProjection, (0, -1, 0)",
         "must be within 0.1 degrees"});
    expectRefused(lp::spotFrame(),
                  [](auto& d) {
                      d.light.direction = {-d.light.direction[0], -d.light.direction[1],
                                           -d.light.direction[2]};
                  },
                  {"light.direction is 180 degrees off the axis of light.shadowViewProjection"});
}

// The frame's frustum is 32 degrees each side of the axis (the test's matrix leaves 2 degrees
// around a 30-degree cone).
TEST_F(LightProjectionGpu, ASpotConeWiderThanItsFrustumIsRefused) {
    auto cone = [](float degrees) {
        return [degrees](lightscatter::FrameDescription& d) {
            d.light.innerConeAngleDegrees = d.light.outerConeAngleDegrees = degrees;
        };
    };
    expectRendered(lp::spotFrame(), cone(32.0f), "a cone as wide as its frustum");
    expectRefused(lp::spotFrame(), cone(32.5f),
                  {"light.outerConeAngleDegrees = 32.5: the cone reaches 0.5",
                   "degrees past the side of light.shadowViewProjection's frustum",
                   "must contain the cone (to 0.01 degrees)"});
    // The engine's mistake: a 45-degree field of view taken for KHR's half angle.
    expectRefused(
        lp::spotFrame(),
        [](auto& d) {
            const glm::vec3 p = lp::vec(d.light.position);
            const glm::mat4 view = glm::lookAtRH(p, p + glm::vec3(0, -1, 0), glm::vec3(0, 0, -1));
            d.light.shadowViewProjection =
                toMat4(testing_support::vulkanPerspective(glm::radians(45.0f), 1.0f, 0.5f, 30.0f,
                                                          false, false) *
                       view);
            d.light.innerConeAngleDegrees = d.light.outerConeAngleDegrees = 45.0f;
        },
        {"light.outerConeAngleDegrees = 45: the cone reaches 22.5 degrees past the side of "
         "light.shadowViewProjection's frustum at clip "});
}

// A light color without a shadow map is projected with the matrix too: its apex and axis must be
// the spot's, but outside its frustum the color is 1 (docs/model.md), so the cone may be wider.
TEST_F(LightProjectionGpu, ACookieAloneIsCheckedAtItsApexButNotAroundTheCone) {
    FrameSpec cookie = lp::spotFrame();
    cookie.shadowed = false;
    cookie.cookie.assign(4 * 4 * 4, 0.5f);
    expectRendered(
        cookie, [](auto& d) { d.light.innerConeAngleDegrees = d.light.outerConeAngleDegrees = 40; },
        "a cookie narrower than the cone");
    expectRefused(cookie,
                  [](auto& d) { d.light.position = lp::moved(d.light.position, 0, 0, 1.0f); },
                  {"light.position is 1 m from the apex of light.shadowViewProjection"});
}

TEST_F(LightProjectionGpu, ASunOffItsShadowAxisIsRefused) {
    expectRendered(
        lp::sunFrame(),
        [](auto& d) {
            d.light.position = {100.0f, -50.0f, 3.0f};
        },
        "a sun's position, which is ignored");
    expectRendered(
        lp::sunFrame(), [](auto& d) { d.light.direction = lp::tilted(d.light.direction, 0.05f); },
        "0.05 degrees off the axis, within the tolerance");
    expectRefused(lp::sunFrame(),
                  [](auto& d) { d.light.direction = lp::tilted(d.light.direction, 2.0f); },
                  {"light.direction is ", " degrees off the axis of light.shadowViewProjection",
                   "must be within 0.1 degrees"});
    // The direction towards the sun instead of the one its light travels.
    expectRefused(lp::sunFrame(),
                  [](auto& d) {
                      d.light.direction = {-d.light.direction[0], -d.light.direction[1],
                                           -d.light.direction[2]};
                  },
                  {"light.direction is 180 degrees off the axis of light.shadowViewProjection",
                   "its depth grows, as light.shadowReversedZ is false"});
    expectRefused(lp::sunFrame(), [](auto& d) { d.light.shadowReversedZ = true; },
                  {"light.direction is 180 degrees off",
                   "its depth falls, as light.shadowReversedZ is true"});
}

// A spot without a shadow map or a light color never uses its matrix: any will do.
TEST_F(LightProjectionGpu, AMatrixThatIsNotUsedIsNotChecked) {
    FrameSpec unshadowed = lp::spotFrame();
    unshadowed.shadowed = false;
    expectRendered(
        unshadowed,
        [](auto& d) {
            const glm::vec3 elsewhere(5.0f, 1.0f, -3.0f);
            d.light.shadowViewProjection =
                toMat4(testing_support::vulkanPerspective(glm::radians(20.0f), 1.0f, 0.5f, 30.0f,
                                                          false, false) *
                       glm::lookAtRH(elsewhere, glm::vec3(0.0f), glm::vec3(0, 1, 0)));
        },
        "another light's matrix on a spot that uses none");
}

// A point light's cube faces are checked at the light (cube_face_checks.cpp): a cube drawn from
// 5 cm beside it is refused, naming the face and the light's position as the frame names them.
// check() validates as record() does; the frame's shadow map stands in for the cube's six layers.
TEST_F(LightProjectionGpu, PointLightCubeFacesAwayFromTheLightAreRefused) {
    TestFrame frame(dev(), lp::spotFrame());
    auto point = [&](const lightscatter::Vec3& cubeAt) {
        auto d = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                   smallSettings(frame.spec().screen));
        d.light.type = lightscatter::LightType::Point;
        d.light.cubeFaceViewProjections = lp::cubeFaces(cubeAt);
        d.shadowMap->arrayLayers = 6;
        return d;
    };
    auto refusal = [&](const lightscatter::FrameDescription& d) -> std::string {
        try {
            plugin().check(d);
        } catch (const lightscatter::InvalidInput& e) {
            return e.what();
        }
        return {};
    };
    const lightscatter::Vec3 at = frame.light().position;
    EXPECT_EQ(refusal(point(at)), "") << "the cube at the light";
    EXPECT_EQ(refusal(lp::asSecondLight(point(at))), "") << "the cube at lights[1]";
    const std::string single = refusal(point(lp::moved(at, 0, 0.05f, 0)));
    EXPECT_TRUE(lp::contains(single,
                             "light.cubeFaceViewProjections[0] does not look along +X from "
                             "light.position"))
        << single;
    auto listedOff = lp::asSecondLight(point(at));
    // One face alone drawn from 5 cm above the light.
    listedOff.lights[1].light.cubeFaceViewProjections[4] =
        lp::cubeFaces(lp::moved(at, 0, 0.05f, 0))[4];
    const std::string listed = refusal(listedOff);
    EXPECT_TRUE(lp::contains(listed,
                             "lights[1]: lights[1].light.cubeFaceViewProjections[4] does not "
                             "look along +Z from lights[1].light.position"))
        << listed;
}
