// A light's identity (LightInput::id, issue #37): the frame's lights are ordered by it inside the
// plugin, so the same lights in another order render the same frame and compile nothing; what the
// plugin keeps for a light (its point-light table, its method's data) follows the light, not its
// place in the list; and a light given as FrameDescription::light is a list of one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "plugin_fixture.h"
#include "support/gpu_test.h"

namespace plugin_test {
namespace {

using lightscatter::Method;
using lightscatter::Profile;

// Three spots over the grille, each its own color and place, all with the frame's shadow map.
std::vector<lightscatter::Light> spots() {
    std::vector<lightscatter::Light> l(3, spotOverGrille());
    l[1].position = {-1.5f, 5.0f, 0.8f};
    l[1].direction = {0.25f, -1.0f, -0.1f};
    l[1].intensity = {15.0f, 25.0f, 40.0f};
    l[2].position = {1.2f, 4.5f, -0.6f};
    l[2].direction = {-0.2f, -1.0f, 0.15f};
    l[2].intensity = {40.0f, 10.0f, 5.0f};
    return l;
}

// `d` with its light replaced by these lights, in this order, each with id `ids[k]` (none where
// `ids` is empty). Each is another chain: the first with the frame's shadow map, the second without
// one, the third with it and brute force, so that the lights' places in a graph are not
// interchangeable (the shadow map is one image, drawn from the first light; each light's matrix is
// its own, from its position along its direction, as the plugin requires).
lightscatter::FrameDescription withLights(lightscatter::FrameDescription d,
                                          const std::vector<lightscatter::Light>& lights,
                                          const std::vector<size_t>& order,
                                          const std::vector<uint64_t>& ids = {}) {
    d.lights.clear();
    for (size_t k : order) {
        lightscatter::LightInput in{lights[k], d.shadowMap, std::nullopt};
        in.light.shadowViewProjection = k == 0 ? d.light.shadowViewProjection
                                               : toMat4(spotShadowMatrix(lights[k], 0.5f, 30.0f));
        if (k == 1) {
            in.shadowMap.reset();
            in.light.shadowMapSize = 0;
        }
        if (k == 2) in.method = Method::BruteForce;
        if (!ids.empty()) in.id = ids[k];
        d.lights.push_back(in);
    }
    d.light = {};
    d.shadowMap.reset();
    d.lightColor.reset();
    return d;
}

bool filled(const lightscatter::FrameReport& r) {
    return std::any_of(r.setupPasses.begin(), r.setupPasses.end(), [](const std::string& p) {
        return p.find("point-light table") != std::string::npos;
    });
}

class LightIdentityGpu : public PluginGpuTest {};

// FrameDescription::light is lights = {light} at the API's edge: the same image and the same
// report, whichever way the light comes.
TEST_F(LightIdentityGpu, TheSameLightGivenEitherWayGivesTheSameFrameAndReport) {
    for (const Method method : {Method::Epipolar, Method::Auto, Method::Froxels}) {
        TestFrame frame(dev(), sceneWith(spotOverGrille()));
        const auto single =
            frame.description(method, Profile::Custom, smallSettings(frame.spec().screen));
        auto list = single;
        list.lights = {{single.light, single.shadowMap, single.lightColor}};
        list.light = {};
        list.shadowMap.reset();
        list.lightColor.reset();
        lightscatter::Plugin one(contextOf(dev())), other(contextOf(dev()));
        frame.resetColor();
        lightscatter::FrameReport a = one.render(single);
        const std::vector<float> colorA = frame.color(), linA = frame.inscatter();
        frame.resetColor();
        lightscatter::FrameReport b = other.render(list);
        const std::vector<float> colorB = frame.color(), linB = frame.inscatter();
        const char* name = lightscatter::methodName(method);
        EXPECT_EQ(std::memcmp(colorA.data(), colorB.data(), colorA.size() * sizeof(float)), 0)
            << name;
        EXPECT_EQ(std::memcmp(linA.data(), linB.data(), linA.size() * sizeof(float)), 0) << name;
        // Everything but the GPU's times.
        for (auto* r : {&a, &b}) {
            r->passes.clear();
            r->totalMilliseconds = 0;
            for (auto& w : r->cpuWork) w.milliseconds = 0;
        }
        EXPECT_EQ(a.method, b.method) << name;
        EXPECT_EQ(a.reason, b.reason) << name;
        EXPECT_EQ(a.notice, b.notice) << name;
        EXPECT_EQ(a.passNames, b.passNames) << name;
        EXPECT_EQ(a.setupPasses, b.setupPasses) << name;
        EXPECT_EQ(a.graphCompiled, b.graphCompiled) << name;
        EXPECT_EQ(a.depthStencilFormat, b.depthStencilFormat) << name;
        ASSERT_EQ(a.lights.size(), 1u);
        ASSERT_EQ(b.lights.size(), 1u);
        EXPECT_EQ(a.lights[0].method, b.lights[0].method) << name;
        EXPECT_EQ(a.lights[0].reason, b.lights[0].reason) << name;
        EXPECT_EQ(std::memcmp(&a.lights[0].settings, &b.lights[0].settings,
                              sizeof(lightscatter::Settings)),
                  0)
            << name;
    }
}

// With ids, the order of the list is the engine's business: every order of the same lights gives
// the same image bit for bit, and only the first compiles a graph.
TEST_F(LightIdentityGpu, ReorderedLightsWithIdsRenderTheSameFrameAndCompileNothing) {
    TestFrame frame(dev(), sceneWith(spotOverGrille()));
    const auto base =
        frame.description(Method::Epipolar, Profile::Custom, smallSettings(frame.spec().screen));
    const std::vector<uint64_t> ids{700, 42, 9000};
    lightscatter::Plugin fresh(contextOf(dev()));
    std::vector<float> first;
    const std::vector<std::vector<size_t>> orders{{0, 1, 2}, {2, 1, 0}, {1, 0, 2},
                                                  {1, 2, 0}, {0, 2, 1}, {2, 0, 1}};
    for (size_t k = 0; k < orders.size(); ++k) {
        frame.resetColor();
        const auto r = fresh.render(withLights(base, spots(), orders[k], ids));
        const std::vector<float> color = frame.color();
        EXPECT_EQ(r.graphCompiled, k == 0) << "order " << k;
        // The report follows the engine's list: each light's settings are its own.
        ASSERT_EQ(r.lights.size(), 3u);
        if (k == 0) {
            first = color;
            continue;
        }
        EXPECT_EQ(std::memcmp(color.data(), first.data(), first.size() * sizeof(float)), 0)
            << "order " << k;
    }
    // The test can fail: without ids a light's identity is its place, so the same lights in
    // another order are another configuration, compiled.
    EXPECT_TRUE(fresh.render(withLights(base, spots(), {0, 1, 2})).graphCompiled);
    EXPECT_TRUE(fresh.render(withLights(base, spots(), {2, 1, 0})).graphCompiled);
}

// A light removed from the middle of the list takes its state with it and leaves the others': no
// table is filled again, and the remaining lights render as they would alone in that frame.
TEST_F(LightIdentityGpu, ALightRemovedFromTheMiddleLeavesTheOthersStateAlone) {
    TestFrame frame(dev(), sceneWith(spotOverGrille()));
    const auto base =
        frame.description(Method::Epipolar, Profile::Custom, smallSettings(frame.spec().screen));
    const std::vector<uint64_t> ids{1, 2, 3};
    lightscatter::Plugin fresh(contextOf(dev()));
    const auto all = fresh.render(withLights(base, spots(), {0, 1, 2}, ids));
    EXPECT_EQ(std::count_if(all.setupPasses.begin(), all.setupPasses.end(),
                            [](const std::string& p) {
                                return p.find("point-light table") != std::string::npos;
                            }),
              3)
        << all.setupPasses.size();
    frame.resetColor();
    const auto two = fresh.render(withLights(base, spots(), {0, 2}, ids));
    EXPECT_FALSE(filled(two)) << "a table was filled again: " << two.setupPasses.size();
    const std::vector<float> kept = frame.color();
    // The same two lights in a plugin that never saw the third.
    lightscatter::Plugin other(contextOf(dev()));
    frame.resetColor();
    other.render(withLights(base, spots(), {0, 2}, ids));
    EXPECT_EQ(std::memcmp(kept.data(), frame.color().data(), kept.size() * sizeof(float)), 0);
}

// A light absent for more than framesInFlight + 60 frames is forgotten with its table: its return
// fills it again. One back sooner finds it kept.
TEST_F(LightIdentityGpu, ALightAbsentLongerThanItsGraceIsForgotten) {
    TestFrame frame(dev(), sceneWith(spotOverGrille(), {16, 16}));
    const auto base =
        frame.description(Method::BruteForce, Profile::Custom, smallSettings(frame.spec().screen));
    lightscatter::PluginCreateInfo info{2, contextOf(dev())};
    lightscatter::Plugin fresh(info);
    const std::vector<uint64_t> ids{5, 6, 7};
    EXPECT_TRUE(filled(fresh.render(withLights(base, spots(), {0, 1}, ids))));
    // Light 6 stays away 30 frames, then comes back: kept.
    for (int k = 0; k < 30; ++k) fresh.render(withLights(base, spots(), {0}, ids));
    EXPECT_FALSE(filled(fresh.render(withLights(base, spots(), {0, 1}, ids))));
    // Away 2 + 60 + 1 frames: forgotten, and filled again on its return.
    for (int k = 0; k < 63; ++k) fresh.render(withLights(base, spots(), {0}, ids));
    const auto back = fresh.render(withLights(base, spots(), {0, 1}, ids));
    EXPECT_EQ(back.setupPasses, std::vector<std::string>{"point-light table (light 1)"});
}

TEST_F(LightIdentityGpu, TwoLightsOfOneIdAreRefused) {
    TestFrame frame(dev(), sceneWith(spotOverGrille()));
    const auto base =
        frame.description(Method::Epipolar, Profile::Custom, smallSettings(frame.spec().screen));
    try {
        plugin().check(withLights(base, spots(), {0, 1, 2}, {4, 8, 4}));
        ADD_FAILURE() << "two lights of id 4 accepted";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_EQ(std::string(e.what()),
                  "lightscatter: lights[2].id = 4 is lights[0]'s too (a light without an id has "
                  "its position): each light's id must differ");
    }
    // A light without an id is its position: id 1 given to another light clashes with it.
    auto mixed = withLights(base, spots(), {0, 1});
    mixed.lights[0].id = 1;
    EXPECT_THROW(plugin().check(mixed), lightscatter::InvalidInput);
}

}  // namespace
}  // namespace plugin_test
