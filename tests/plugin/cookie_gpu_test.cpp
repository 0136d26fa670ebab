// Cookies (issue #25): a spot's or directional light's light-color image, projected with its
// shadowViewProjection, with a shadow map and without. Each method that honours an unshadowed
// cookie is held against the float64 model with the cookie (model_conversion.h's
// float64WithCookie), with bounds that the uncookied light and a shifted cookie miss; a uniform
// cookie scales the uncookied Lin; the methods that cannot vary the color along a ray refuse it in
// one line, and auto picks one that honours it.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "model_conversion.h"
#include "plugin_fixture.h"

namespace plugin_test {
namespace {

using lightscatter::Method;
using lightscatter::Profile;

constexpr uint32_t kCookieSize = 32;

// Stained glass: 4 x 4 panes of 8 x 8 texels in six colors, with dark leading (0.05) one texel
// wide along the panes' edges.
std::vector<float> stainedGlass(uint32_t shift = 0) {
    const float panes[6][3] = {{0.9f, 0.2f, 0.15f},  {0.2f, 0.8f, 0.25f}, {0.2f, 0.3f, 0.95f},
                               {0.95f, 0.85f, 0.2f}, {0.7f, 0.25f, 0.8f}, {0.95f, 0.95f, 0.9f}};
    std::vector<float> t(size_t{kCookieSize} * kCookieSize * 4, 1.0f);
    for (uint32_t y = 0; y < kCookieSize; ++y)
        for (uint32_t x = 0; x < kCookieSize; ++x) {
            const uint32_t sx = (x + shift) % kCookieSize;
            float* p = &t[(size_t{y} * kCookieSize + x) * 4];
            const bool leading = sx % 8 == 0 || y % 8 == 0;
            for (uint32_t k = 0; k < 3; ++k)
                p[k] = leading ? 0.05f : panes[(sx / 8 + 3 * (y / 8)) % 6][k];
        }
    return t;
}

std::vector<float> uniformCookie(float r, float g, float b) {
    std::vector<float> t(size_t{kCookieSize} * kCookieSize * 4, 1.0f);
    for (size_t i = 0; i < t.size(); i += 4) {
        t[i] = r;
        t[i + 1] = g;
        t[i + 2] = b;
    }
    return t;
}

// The spot over the grille without a shadow map (flatSpot) and a sun, each with `cookie`.
FrameSpec cookieSpot(std::vector<float> cookie) {
    FrameSpec s = flatSpot();
    s.cookie = std::move(cookie);
    return s;
}

FrameSpec cookieSun(std::vector<float> cookie) {
    FrameSpec s = sceneWith(sunThroughGrille(), {48, 32});
    s.shadowed = false;
    s.sceneRadius = 80.0f;  // the cookie's box holds every ray of the view
    s.cookie = std::move(cookie);
    return s;
}

// Settings that make each method's own error small beside the cookie's: 256 cone-march samples,
// 256 planes into a float32 target.
lightscatter::Settings accurate(const FrameSpec& spec) {
    lightscatter::Settings s = smallSettings(spec.screen);
    s.coneMarch.samples = 256;
    s.planes.count = 256;
    s.planes.target = lightscatter::PlaneTarget::Float32;
    return s;
}

class CookieGpu : public PluginGpuTest {
  protected:
    std::vector<float> render(Method method, const FrameSpec& spec,
                              lightscatter::FrameReport* report = nullptr) {
        TestFrame frame(dev(), spec);
        const auto r = plugin().render(frame.description(method, Profile::Custom, accurate(spec)));
        if (report) *report = r;
        return frame.inscatter();
    }

    // Each method's Lin with `spec`'s cookie within its bound of the float64 model with the
    // cookie, and the same light without the cookie, and with the cookie's glass moved one pane
    // over (the same leading), outside it.
    void check(const char* what, const FrameSpec& spec, const std::vector<MethodBound>& bounds) {
        TestFrame truth(dev(), spec);
        const std::vector<float> want = float64WithCookie(truth);
        FrameSpec plain = spec;
        plain.cookie.clear();
        FrameSpec shifted = spec;
        shifted.cookie = stainedGlass(8);
        for (const MethodBound& b : bounds) {
            SCOPED_TRACE(std::string(what) + ", " + lightscatter::methodName(b.method));
            const ErrorStats e = compare(render(b.method, spec), want);
            const ErrorStats p = compare(render(b.method, plain), want);
            const ErrorStats s = compare(render(b.method, shifted), want);
            std::printf(
                "%s, %s: mean %.2e max %.2e of the peak; without the cookie %.2e, the glass one "
                "pane over %.2e\n",
                what, lightscatter::methodName(b.method), e.meanRelative, e.maxRelative,
                p.meanRelative, s.meanRelative);
            ASSERT_GT(e.peak, 0.0);
            EXPECT_EQ(e.nonFinite, 0u);
            EXPECT_LT(e.meanRelative, b.meanRelative);
            EXPECT_GT(p.meanRelative, b.meanRelative) << "the bound misses a missing cookie";
            EXPECT_GT(s.meanRelative, b.meanRelative) << "the bound misses a shifted cookie";
        }
    }
};

// Without a shadow map: epipolar and brute force march the color per pixel (a piece per texel row
// or column crossed), cone-march and the planes sample it at their points. Each bound is about five
// times what lavapipe measured (docs/methods.md, "Cookies"), and the light without its cookie, or
// with its glass one pane over, misses every one.
TEST_F(CookieGpu, UnshadowedStainedGlassMatchesTheFloat64Model) {
    check("spot, no shadow map", cookieSpot(stainedGlass()),
          {{Method::Epipolar, 5e-5},
           {Method::BruteForce, 5e-5},
           {Method::ConeMarch, 5e-5},
           {Method::Planes, 1.5e-3},
           {Method::BeamTreeSampling, 1.5e-3}});
    // The planes' head and tail outside their slab take the directional closed form, uncoloured.
    check("sun, no shadow map", cookieSun(stainedGlass()),
          {{Method::Epipolar, 1e-3},
           {Method::BruteForce, 1e-3},
           {Method::ConeMarch, 5e-4},
           {Method::Planes, 2e-2}});
}

// With a shadow map that shadows nothing (an empty scene): the shadowed marches look the color up
// at each shadow-map step's end, and colour only inside the shadow map's frustum (not between the
// light and its near plane, where a few pixels near the spot's apex lose their color).
TEST_F(CookieGpu, ShadowedStainedGlassMatchesTheFloat64Model) {
    FrameSpec spec = cookieSpot(stainedGlass());
    spec.scene = Scene{};
    spec.shadowed = true;
    check("spot, shadowed by nothing", spec,
          {{Method::Epipolar, 3e-3},
           {Method::BruteForce, 3e-3},
           {Method::ConeMarch, 5e-5},
           {Method::Planes, 1.5e-3}});
}

// A uniform cookie of color c is c times the uncookied light, for each method that honours it:
// the march's pieces add up to the closed form, and the sampling methods' samples are scaled.
TEST_F(CookieGpu, AUniformCookieScalesTheUncookiedLin) {
    const float c[3] = {0.8f, 0.5f, 0.25f};
    struct Row {
        FrameSpec base;
        Method method;
        double mean, max;  // of the peak
    };
    std::vector<Row> rows;
    for (Method m : {Method::Epipolar, Method::BruteForce, Method::ConeMarch, Method::Planes,
                     Method::BeamTreeSampling})
        rows.push_back({cookieSpot({}), m, 1e-5, 1e-3});
    for (Method m : {Method::Epipolar, Method::BruteForce, Method::ConeMarch})
        rows.push_back({cookieSun({}), m, 1e-4, 2e-3});
    // A sun's planes add the closed form, uncoloured, before and behind their slab.
    rows.push_back({cookieSun({}), Method::Planes, 5e-3, 1e-2});
    for (const Row& row : rows) {
        const bool spot = row.base.light.type == lightscatter::LightType::Spot;
        SCOPED_TRACE(std::string(spot ? "spot, " : "sun, ") + lightscatter::methodName(row.method));
        FrameSpec cookied = row.base;
        cookied.cookie = uniformCookie(c[0], c[1], c[2]);
        std::vector<float> scaled = render(row.method, row.base);
        for (size_t i = 0; i < scaled.size(); ++i)
            if (i % 4 != 3) scaled[i] *= c[i % 4];
        const ErrorStats e = compare(render(row.method, cookied), scaled);
        std::printf("uniform cookie, %s, %s: mean %.2e max %.2e of the peak\n",
                    spot ? "spot" : "sun", lightscatter::methodName(row.method), e.meanRelative,
                    e.maxRelative);
        ASSERT_GT(e.peak, 0.0);
        EXPECT_LT(e.meanRelative, row.mean);
        EXPECT_LT(e.maxRelative, row.max);
    }
}

std::string refusalOf(Method method, const FrameSpec& spec,
                      const lightscatter::Settings& settings) {
    TestFrame frame(testing_support::device(), spec);
    try {
        plugin().render(frame.description(method, Profile::Custom, settings));
    } catch (const lightscatter::InvalidInput& e) {
        return e.what();
    }
    return "";
}

// The methods that integrate an unshadowed light in closed form refuse its cookie in one line
// naming themselves and the field; auto marches it.
TEST_F(CookieGpu, MethodsThatCannotVaryTheColorRefuseItAndAutoPicksOneThatCan) {
    const FrameSpec spot = cookieSpot(stainedGlass());
    const lightscatter::Settings settings = accurate(spot);
    // The methods that take it instead come from their caps (lightscatter::methodInfo()).
    EXPECT_EQ(refusalOf(Method::Analytic, spot, settings),
              "lightscatter: method analytic cannot vary the light's color along the ray: "
              "lightColor without a shadow map needs epipolar, brute-force, cone-march, planes, "
              "beam-tree-sampling, froxels or auto");
    const std::string tree =
        "lightscatter: method beam-tree-analytic cannot vary the light's color along the ray: "
        "lightColor without a shadow map needs epipolar, brute-force, cone-march, planes, "
        "beam-tree-sampling, froxels or auto";
    EXPECT_EQ(refusalOf(Method::BeamTreeAnalytic, spot, settings), tree);
    FrameSpec shadowed = spot;
    shadowed.shadowed = true;
    EXPECT_EQ(refusalOf(Method::BeamTreeAnalytic, shadowed, settings),
              "lightscatter: method beam-tree-analytic cannot vary the light's color along the "
              "ray: lightColor needs epipolar, brute-force, cone-march, planes, "
              "beam-tree-sampling, froxels or auto");

    // A point light has no single projection.
    FrameSpec point = spot;
    point.light.type = lightscatter::LightType::Point;
    EXPECT_EQ(refusalOf(Method::BruteForce, point, settings),
              "lightscatter: lightColor is not supported with a point light: a light-space color "
              "texture needs a spot or directional light's single projection "
              "(light.shadowViewProjection)");

    // Auto: the per-pixel march, reported as epipolar (whose unshadowed form it is).
    lightscatter::FrameReport report;
    render(Method::Auto, spot, &report);
    EXPECT_EQ(report.method, "epipolar");
    EXPECT_NE(report.reason.find("light color: marched per pixel"), std::string::npos)
        << report.reason;
    // Seed 004's simplified model has only closed forms.
    lightscatter::Settings simplified = settings;
    simplified.lightModel = lightscatter::LightModel::Simplified;
    EXPECT_EQ(refusalOf(Method::Auto, spot, simplified),
              "lightscatter: custom.lightModel = simplified (seed 004's light model): no method "
              "that honours it takes this light (" +
                  tree.substr(std::string("lightscatter: ").size()) + ")");
}

// The projection is required: without a shadow map the default all-zero matrix is refused.
TEST_F(CookieGpu, ACookieWithoutAShadowMapNeedsItsProjection) {
    const FrameSpec spot = cookieSpot(stainedGlass());
    TestFrame frame(dev(), spot);
    lightscatter::FrameDescription d =
        frame.description(Method::BruteForce, Profile::Custom, accurate(spot));
    d.light.shadowViewProjection = {};
    try {
        plugin().render(d);
        ADD_FAILURE() << "a zero shadowViewProjection was accepted";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_EQ(std::string(e.what()),
                  "lightscatter: light.shadowViewProjection is singular (all zero): with "
                  "lightColor it must be the world -> light clip matrix the color is projected "
                  "with");
    }
}

}  // namespace
}  // namespace plugin_test
