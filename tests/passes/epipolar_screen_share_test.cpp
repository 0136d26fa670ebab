// A light's epipolar lines follow its screen rectangle (passes/epipolar/screen_share.h), without a
// device: the whole screen keeps the settings' sizes and seed 000's shrunk boundary to the bit; a
// smaller rectangle halves the slices by its perimeter and the samples by its diagonal, never
// below the settings' density, nor below the floor, nor off the march's grain; and a share near a
// step keeps the frame before's sizes until it has moved past the step by a margin. A spot seen
// from outside its cone takes a window of its border's slices: every slice whose line crosses the
// cone's corners' directions, and its neighbours; the whole border where the corners surround the
// light or the light is outside the border.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "epipolar/screen_share.h"

namespace {

constexpr VkExtent2D kScreen{1920, 1080};

lightscatter::EpipolarSettings balanced() {
    lightscatter::EpipolarSettings s;
    s.slices = 1024;
    s.samplesPerSlice = 1024;
    s.initialSampleStep = 16;
    return s;
}

VkRect2D centred(uint32_t w, uint32_t h) {
    return {{static_cast<int32_t>((kScreen.width - w) / 2),
             static_cast<int32_t>((kScreen.height - h) / 2)},
            {w, h}};
}

TEST(EpipolarScreenShare, TheWholeScreenKeepsTheSettingsAndTheShrunkBoundary) {
    const ls::LineSizes sizes = ls::sizesForRect(balanced(), kScreen, {{0, 0}, kScreen}, nullptr);
    EXPECT_EQ(sizes.slices, 1024u);
    EXPECT_EQ(sizes.samples, 1024u);
    // The shaders' boundary before it came from the constants: -1 + 1/W and 1 - 1/W, in float.
    const glm::vec4 b = ls::lineBounds(kScreen, {{0, 0}, kScreen});
    EXPECT_EQ(b.x, -1.0f + 1.0f / 1920.0f);
    EXPECT_EQ(b.y, -1.0f + 1.0f / 1080.0f);
    EXPECT_EQ(b.z, 1.0f - 1.0f / 1920.0f);
    EXPECT_EQ(b.w, 1.0f - 1.0f / 1080.0f);
}

TEST(EpipolarScreenShare, ARectangleKeepsTheDensityOfItsBorderAndLines) {
    // A quarter of each side: the perimeter's and the diagonal's share are 1/4, two halvings.
    ls::LineSizes sizes = ls::sizesForRect(balanced(), kScreen, centred(480, 270), nullptr);
    EXPECT_EQ(sizes.slices, 256u);
    EXPECT_EQ(sizes.samples, 256u);
    // A little over a quarter: one halving only (the density never falls below the settings').
    sizes = ls::sizesForRect(balanced(), kScreen, centred(500, 290), nullptr);
    EXPECT_EQ(sizes.slices, 512u);
    EXPECT_EQ(sizes.samples, 512u);
    // A wide, flat strip: its perimeter is over half the screen's, its diagonal not.
    sizes = ls::sizesForRect(balanced(), kScreen, centred(1900, 40), nullptr);
    EXPECT_EQ(sizes.slices, 1024u);
    EXPECT_EQ(sizes.samples, 1024u / 1u);
    // A few pixels: the floor of 64 each.
    sizes = ls::sizesForRect(balanced(), kScreen, centred(3, 3), nullptr);
    EXPECT_EQ(sizes.slices, 64u);
    EXPECT_EQ(sizes.samples, 64u);
}

TEST(EpipolarScreenShare, SizesStayOnTheMarchsGrain) {
    // 1008 samples are a multiple of the initial step 16; 504 is not: no halving.
    lightscatter::EpipolarSettings s = balanced();
    s.samplesPerSlice = 1008;
    EXPECT_EQ(ls::sizesForRect(s, kScreen, centred(480, 270), nullptr).samples, 1008u);
    // 1000 slices halve to 500 (a multiple of 4), not to 250.
    s.slices = 1000;
    EXPECT_EQ(ls::sizesForRect(s, kScreen, centred(480, 270), nullptr).slices, 500u);
}

TEST(EpipolarScreenShare, AShareNearAStepKeepsTheFrameBeforesSizes) {
    const ls::LineSizes half{512, 512};
    // Just under a quarter: two halvings alone, but one from the frame before's until the share
    // is 15% under the step.
    EXPECT_EQ(ls::sizesForRect(balanced(), kScreen, centred(470, 264), &half), half);
    EXPECT_EQ(ls::sizesForRect(balanced(), kScreen, centred(400, 225), &half),
              (ls::LineSizes{256, 256}));
    // Growing takes effect at once.
    const ls::LineSizes quarter{256, 256};
    EXPECT_EQ(ls::sizesForRect(balanced(), kScreen, centred(500, 290), &quarter), half);
}

TEST(EpipolarScreenShare, ARectangleOfOnePixelIsWidenedToTwo) {
    const glm::vec4 b = ls::lineBounds(kScreen, {{1919, 500}, {1, 1}});
    EXPECT_LT(b.x, b.z);
    EXPECT_LT(b.y, b.w);
    EXPECT_FLOAT_EQ(b.z, 1.0f - 1.0f / 1920.0f);
}

// The corners of a spot's pyramid as lightScreenCorners gives them (NDC, apex first): the apex at
// `light` and eight points on a circle of `radius` around `centre`.
std::vector<glm::vec2> pyramid(glm::vec2 light, glm::vec2 centre, float radius) {
    std::vector<glm::vec2> c{light};
    for (int k = 0; k < 8; ++k) {
        const float a = std::numbers::pi_v<float> / 4.0f * static_cast<float>(k);
        c.push_back(centre + radius * glm::vec2(std::cos(a), std::sin(a)));
    }
    return c;
}

// Where border slice g's line leaves the border, as shaders/epipolar/epipolar_geometry.glsl walks
// it (corner 0 the top left, then clockwise on the screen), in double.
glm::dvec2 exitOf(uint32_t g, uint32_t border, glm::dvec4 b) {
    const double u = (g + 0.5) / border * 4.0;
    const int edge = std::min(static_cast<int>(u), 3);
    const glm::dvec2 corners[4] = {{b.x, b.y}, {b.z, b.y}, {b.z, b.w}, {b.x, b.w}};
    return corners[edge] + (u - edge) * (corners[(edge + 1) % 4] - corners[edge]);
}

// Whether the window's slices that a lit pixel may read (the wedge a later light draws) hold
// border slice g; they lie within the window.
bool holds(const ls::LineWindow& w, int64_t g) {
    const auto n = static_cast<int64_t>(w.border);
    EXPECT_LE(w.neededFrom + w.needed, w.slices);
    const int64_t from = static_cast<int64_t>(w.first) + w.neededFrom;
    return ((g - from) % n + n) % n < w.needed;
}

// Whether border slice g's line from a light off the border crosses it, as
// shaders/epipolar/slice_end_points.comp decides (its exit edge faces away from the light, and the
// line enters the border before its exit).
bool crosses(uint32_t g, uint32_t border, glm::dvec4 b, glm::dvec2 light) {
    const glm::dvec2 e = exitOf(g, border, b);
    const glm::dvec2 d = e - light;
    const double u = (g + 0.5) / border * 4.0;
    const int edge = std::min(static_cast<int>(u), 3);
    const glm::dvec2 normals[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    if (glm::dot(d, normals[edge]) <= 0.0) return false;
    double tNear = -1e300, tFar = 1e300;
    const double lo[2] = {b.x, b.y}, hi[2] = {b.z, b.w};
    for (int a = 0; a < 2; ++a) {
        if (std::fabs(d[a]) < 1e-300) continue;
        const double t0 = (lo[a] - light[a]) / d[a], t1 = (hi[a] - light[a]) / d[a];
        tNear = std::max(tNear, std::min(t0, t1));
        tFar = std::min(tFar, std::max(t0, t1));
    }
    return tNear < tFar && tNear < 1.0 - 1e-6;
}

// Every border slice whose exit lies in the corners' directions from the light (and, off the
// border, whose line crosses it) is in the window, with both neighbours (a pixel between two
// slices reads both).
void expectCovers(const ls::LineWindow& w, const std::vector<glm::vec2>& corners, glm::vec4 bounds,
                  const char* what) {
    const glm::dvec2 light(corners[0]);
    glm::dvec2 mean(0.0);
    for (size_t i = 1; i < corners.size(); ++i)
        mean += glm::normalize(glm::dvec2(corners[i]) - light);
    auto angle = [&](glm::dvec2 d) {
        return std::atan2(mean.x * d.y - mean.y * d.x, glm::dot(mean, d));
    };
    double lo = 10.0, hi = -10.0;
    for (size_t i = 1; i < corners.size(); ++i) {
        lo = std::min(lo, angle(glm::dvec2(corners[i]) - light));
        hi = std::max(hi, angle(glm::dvec2(corners[i]) - light));
    }
    const bool off =
        !(light.x > bounds.x && light.x < bounds.z && light.y > bounds.y && light.y < bounds.w);
    int inside = 0;
    for (uint32_t g = 0; g < w.border; ++g) {
        // Off the border, a slice whose line does not cross it serves no pixel.
        if (off && !crosses(g, w.border, glm::dvec4(bounds), light)) continue;
        const double a = angle(exitOf(g, w.border, glm::dvec4(bounds)) - light);
        if (a < lo || a > hi) continue;
        ++inside;
        for (int64_t k = -1; k <= 1; ++k)
            EXPECT_TRUE(holds(w, static_cast<int64_t>(g) + k))
                << what << ": border slice " << g + k << " of " << w.border << ", window "
                << w.slices << " from " << w.first;
    }
    EXPECT_GT(inside, 0) << what;
}

TEST(EpipolarScreenShare, ASpotSeenFromOutsideItsConeTakesTheWedgesSlices) {
    const glm::vec4 b = ls::lineBounds(kScreen, {{0, 0}, kScreen});
    // A light near the top, its cone down towards the floor: a wedge of some 35 degrees.
    const auto down = pyramid({0.1f, -0.8f}, {0.0f, 0.9f}, 0.5f);
    const ls::LineWindow w = ls::lineWindow(down, down[0], b, 1024, nullptr);
    EXPECT_EQ(w.border, 1024u);
    EXPECT_TRUE(w.part());
    EXPECT_LE(w.slices, 256u);
    EXPECT_EQ(w.slices & (w.slices - 1), 0u) << "a power-of-two share of the border";
    expectCovers(w, down, b, "down");
    // Its window leaves by the bottom edge (border slices 512 to 767), centred on what it needs.
    EXPECT_GE(w.first, 500u);
    EXPECT_LE(w.first + w.slices, 780u);
    // The same wedge across the border's start (the top left corner): the window wraps.
    const auto corner = pyramid({0.5f, 0.5f}, {-0.95f, -0.95f}, 0.1f);
    const ls::LineWindow wrap = ls::lineWindow(corner, corner[0], b, 1024, nullptr);
    EXPECT_TRUE(wrap.part());
    EXPECT_GT(wrap.first + wrap.slices, 1024u) << "from " << wrap.first;
    expectCovers(wrap, corner, b, "across the start");
    // A very narrow cone still keeps the floor of 64 slices.
    const auto thin = pyramid({0.1f, -0.8f}, {0.1f, 0.9f}, 0.01f);
    EXPECT_EQ(ls::lineWindow(thin, thin[0], b, 1024, nullptr).slices, 64u);
}

TEST(EpipolarScreenShare, ASpotAroundTheCameraTakesEverySlice) {
    const glm::vec4 b = ls::lineBounds(kScreen, {{0, 0}, kScreen});
    // The camera inside the cone: its corners surround the light's point.
    const auto around = pyramid({0.1f, 0.1f}, {0.0f, 0.0f}, 0.6f);
    EXPECT_EQ(ls::lineWindow(around, around[0], b, 1024, nullptr), ls::wholeBorder(1024));
    // A wedge wider than a half-turn less the margin: whole.
    const auto wide = pyramid({0.0f, 0.0f}, {0.0f, 0.05f}, 0.06f);
    EXPECT_EQ(ls::lineWindow(wide, wide[0], b, 1024, nullptr), ls::wholeBorder(1024));
    // A corner on the light's point: no direction to it.
    auto onPoint = pyramid({0.1f, -0.8f}, {0.0f, 0.9f}, 0.5f);
    onPoint[3] = onPoint[0];
    EXPECT_EQ(ls::lineWindow(onPoint, onPoint[0], b, 1024, nullptr), ls::wholeBorder(1024));
}

TEST(EpipolarScreenShare, AWideningConeGrowsItsWindowAtOnceAndShrinksItLate) {
    // The wedge widens a step at a time, then narrows back, each frame given the one before's
    // window: the count never falls below the slices the wedge needs, and a count that grew at
    // some width shrinks back only at a narrower one.
    const glm::vec4 b = ls::lineBounds(kScreen, {{0, 0}, kScreen});
    std::vector<uint32_t> up, downCounts;
    ls::LineWindow w{};
    const int steps = 60;
    for (int i = 0; i <= steps; ++i) {
        const auto c = pyramid({0.1f, -0.8f}, {0.1f, 0.9f}, 0.01f + 0.02f * static_cast<float>(i));
        w = ls::lineWindow(c, c[0], b, 1024, w.border != 0 ? &w : nullptr);
        expectCovers(w, c, b, "widening");
        up.push_back(w.slices);
    }
    for (int i = steps; i >= 0; --i) {
        const auto c = pyramid({0.1f, -0.8f}, {0.1f, 0.9f}, 0.01f + 0.02f * static_cast<float>(i));
        w = ls::lineWindow(c, c[0], b, 1024, &w);
        expectCovers(w, c, b, "narrowing");
        downCounts.push_back(w.slices);
    }
    std::reverse(downCounts.begin(), downCounts.end());
    bool later = false;
    for (int i = 0; i <= steps; ++i) {
        EXPECT_GE(downCounts[i], up[i]) << "step " << i;
        later = later || downCounts[i] > up[i];
    }
    EXPECT_TRUE(later) << "no width kept the wider window on the way back";
    EXPECT_GT(up.back(), up.front());
}

TEST(EpipolarScreenShare, ALightOffTheBorderTakesTheSlicesThatCrossIt) {
    const glm::dvec4 b(ls::lineBounds(kScreen, {{0, 0}, kScreen}));
    // Above the screen (a sun out of view, or a spot's apex above it), beside it, and a spot off
    // the border whose cone reaches back into it.
    for (const glm::vec2 light : {glm::vec2(0.2f, -1.6f), glm::vec2(-3.0f, 0.4f),
                                  glm::vec2(2.5f, 2.5f), glm::vec2(0.0f, 40.0f)}) {
        const ls::LineWindow w = ls::lineWindow({}, light, glm::vec4(b), 1024, nullptr);
        int crossing = 0;
        for (uint32_t g = 0; g < 1024; ++g) {
            if (!crosses(g, 1024, b, glm::dvec2(light))) continue;
            ++crossing;
            for (int64_t k = -1; k <= 1; ++k)
                EXPECT_TRUE(holds(w, static_cast<int64_t>(g) + k))
                    << "light (" << light.x << ", " << light.y << "): border slice " << g + k
                    << ", window " << w.slices << " from " << w.first;
        }
        EXPECT_GT(crossing, 0);
        // At most the crossing slices, two each side and the next eighth of the border.
        EXPECT_TRUE(w.part()) << light.x << ", " << light.y << ": " << crossing << " cross";
        EXPECT_LE(w.slices, static_cast<uint32_t>(crossing) + 4u + 128u);
    }
    // A spot above the screen shining down into it: the overlap of its cone and the border's.
    const auto spot = pyramid({0.1f, -1.5f}, {0.0f, 0.9f}, 0.4f);
    const ls::LineWindow cone = ls::lineWindow(spot, spot[0], glm::vec4(b), 1024, nullptr);
    const ls::LineWindow rect = ls::lineWindow({}, spot[0], glm::vec4(b), 1024, nullptr);
    EXPECT_LT(cone.slices, rect.slices);
    expectCovers(cone, spot, glm::vec4(b), "a spot above the screen");
    // So far off that its lines are parallel in float: every slice.
    EXPECT_EQ(ls::lineWindow({}, {0.0f, 1e5f}, glm::vec4(b), 1024, nullptr), ls::wholeBorder(1024));
}

}  // namespace
