// The CPU reference renderer against cases solved by hand: pixel rays in the GPU's conventions,
// the sky rule, lit intervals of an occluder's shadow volume (a slab for a directional light, a
// pyramid for point and spot lights), and the properties of the image as a whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "exact_renderer/reference_renderer.h"
#include "float64_model/closed_forms.h"
#include "float64_model/inscatter_integral.h"
#include "float64_model/optical_depth.h"
#include "float64_model/ray_geometry.h"
#include "scene/scene.h"

namespace {

using host::reference::ReferenceImage;
using host::reference::ReferenceOptions;
using host::reference::ReferenceScene;
using host::reference::renderReference;
using ls::ref::Interval;

class MeshBuilder {
  public:
    // A quad a-b-c-d as two triangles sharing the diagonal a-c.
    MeshBuilder& quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
        const auto base = static_cast<uint32_t>(mesh_.vertices.size());
        for (const glm::vec3& p : {a, b, c, d}) mesh_.vertices.push_back({p, {0, 1, 0}, {0, 0}});
        for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh_.indices.push_back(base + i);
        return *this;
    }
    // A horizontal square [x0, x1] x [z0, z1] at height y.
    MeshBuilder& horizontal(float y, float x0, float x1, float z0, float z1) {
        return quad({x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1});
    }
    host::MeshData build() {
        host::MeshData out = mesh_;
        out.primitives = {{0, static_cast<uint32_t>(out.indices.size()), -1}};
        return out;
    }

  private:
    host::MeshData mesh_;
};

host::SceneDesc baseScene() {
    host::SceneDesc s;
    s.camera.position = {0.0f, 1.5f, 6.0f};
    s.camera.target = {0.0f, 0.5f, 0.0f};
    s.camera.fovYDegrees = 60.0f;
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 100.0f;
    s.medium.betaR = {0.001f, 0.002f, 0.004f};
    s.medium.betaM = {0.02f, 0.02f, 0.02f};
    s.medium.g = 0.6f;
    s.medium.maxDistance = 50.0f;
    s.light.type = lightscatter::LightType::Directional;
    s.light.direction = {0.3f, -1.0f, 0.2f};
    s.light.intensity = {10.0f, 9.0f, 8.0f};
    return s;
}

// a + b s <= 0 along the ray.
struct Affine {
    double a, b;
};

// Where every constraint holds on [0, length]; nothing if that is empty or a single point.
std::optional<Interval> solve(const std::vector<Affine>& constraints, double length) {
    double lo = 0.0, hi = length;
    for (const Affine& c : constraints) {
        if (c.b > 0.0) hi = std::min(hi, -c.a / c.b);
        if (c.b < 0.0) lo = std::max(lo, -c.a / c.b);
        if (c.b == 0.0 && c.a > 0.0) return std::nullopt;
    }
    if (!(lo < hi)) return std::nullopt;
    return Interval{lo, hi};
}

// [0, length] without the shadow.
std::vector<Interval> complement(const std::optional<Interval>& shadow, double length) {
    if (!shadow) return {{0.0, length}};
    std::vector<Interval> lit;
    if (shadow->begin > 0.0) lit.push_back({0.0, shadow->begin});
    if (shadow->end < length) lit.push_back({shadow->end, length});
    return lit;
}

// Whether every piece between these points is at least two sample spacings long, so that sampling
// cannot step over one (the only approximation of the lit-interval search).
bool resolvable(std::vector<double> points, double spacing) {
    std::sort(points.begin(), points.end());
    for (std::size_t i = 1; i < points.size(); ++i) {
        const double gap = points[i] - points[i - 1];
        if (gap > 0.0 && gap < 2.0 * spacing) return false;
    }
    return true;
}

::testing::AssertionResult sameIntervals(const std::vector<Interval>& actual,
                                         const std::vector<Interval>& expected, double tol) {
    auto print = [](const std::vector<Interval>& v) {
        std::string s;
        for (const Interval& i : v)
            s += "[" + std::to_string(i.begin) + ", " + std::to_string(i.end) + "] ";
        return s;
    };
    bool same = actual.size() == expected.size();
    for (std::size_t i = 0; same && i < actual.size(); ++i) {
        same = std::abs(actual[i].begin - expected[i].begin) <= tol &&
               std::abs(actual[i].end - expected[i].end) <= tol;
    }
    if (same) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "got " << print(actual) << "expected "
                                         << print(expected) << "(tolerance " << tol << ")";
}

::testing::AssertionResult near3(const glm::dvec3& actual, const glm::dvec3& expected, double tol) {
    for (int c = 0; c < 3; ++c) {
        if (!(std::abs(actual[c] - expected[c]) <= tol)) {
            return ::testing::AssertionFailure() << "channel " << c << ": " << actual[c] << " vs "
                                                 << expected[c] << " (tolerance " << tol << ")";
        }
    }
    return ::testing::AssertionSuccess();
}

double maxAbs(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

TEST(ReferenceRenderer, ConvertsTheScenesLightAndMedium) {
    host::LightDesc l;
    l.type = lightscatter::LightType::Spot;
    l.position = {1, 2, 3};
    l.direction = {0, -2, 0};
    l.intensity = {4, 5, 6};
    l.innerConeAngleDegrees = l.outerConeAngleDegrees = 30.0f;
    l.range = 7.0f;
    l.radius = 0.25f;
    const ls::ref::Light light = host::reference::toReferenceLight(l);
    EXPECT_EQ(light.type, ls::ref::Light::Spot);
    EXPECT_NEAR(light.outerAngle, ls::ref::kPi / 6.0, 1e-15);
    EXPECT_NEAR(light.innerAngle, ls::ref::kPi / 6.0, 1e-15);
    EXPECT_EQ(light.direction, glm::dvec3(0, -1, 0));
    EXPECT_EQ(light.position, glm::dvec3(1, 2, 3));
    EXPECT_EQ(light.intensity, glm::dvec3(4, 5, 6));
    EXPECT_EQ(light.range, 7.0);
    EXPECT_EQ(light.r0, 0.25);

    host::MediumDesc m;
    m.betaR = {1, 2, 3};
    m.betaM = {4, 5, 6};
    m.sigmaA = {0.5f, 0.25f, 0.125f};
    m.g = 0.5f;
    m.phase = lightscatter::MiePhase::Isotropic;
    m.maxDistance = 77.0f;
    const ls::ref::Medium medium = host::reference::toReferenceMedium(m);
    EXPECT_EQ(medium.betaT(), glm::dvec3(5.5, 7.25, 9.125));
    EXPECT_EQ(medium.miePhase, ls::ref::Medium::Isotropic);
    EXPECT_EQ(medium.g, 0.5);
    EXPECT_EQ(medium.maxDistance, 77.0);
}

TEST(ReferenceRenderer, PixelRaysFollowTheGpuConventions) {
    host::SceneDesc s = baseScene();
    s.camera.position = {0.0f, 1.0f, 5.0f};
    s.camera.target = {0.0f, 1.0f, 0.0f};
    const uint32_t w = 64, h = 32;
    const ReferenceScene scene(s, MeshBuilder().build(), w, h);
    EXPECT_LT(glm::length(scene.camera().eye() - glm::dvec3(0, 1, 5)), 1e-6);
    EXPECT_LT(glm::length(scene.camera().axis() - glm::dvec3(0, 0, -1)), 1e-6);
    // Looking down -z with +y up: NDC x right, NDC y down (Vulkan), pixel centres.
    const double t = std::tan(glm::radians(30.0));
    const double aspect = static_cast<double>(w) / h;
    for (uint32_t y : {0u, 7u, 31u}) {
        for (uint32_t x : {0u, 40u, 63u}) {
            const double nx = (x + 0.5) / w * 2.0 - 1.0, ny = (y + 0.5) / h * 2.0 - 1.0;
            const glm::dvec3 expected = glm::normalize(glm::dvec3(nx * t * aspect, -ny * t, -1.0));
            const ls::ref::Ray ray = scene.pixelRay(x, y);
            EXPECT_LT(glm::length(ray.direction - expected), 1e-6) << x << ", " << y;
            EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-15);
            EXPECT_EQ(ray.origin, scene.camera().eye());
        }
    }
    EXPECT_GT(scene.pixelRay(0, 0).direction.y, 0.0);  // row 0 is the top of the image
    EXPECT_LT(scene.pixelRay(0, 0).direction.x, 0.0);
}

TEST(ReferenceRenderer, UnshadowedDirectionalEqualsTheClosedFormPerPixel) {
    host::SceneDesc s = baseScene();
    s.camera.farPlane = 20.0f;  // part of the ground lies beyond it and is sky
    s.medium.maxDistance = 1000.0f;
    const host::MeshData mesh = MeshBuilder().horizontal(0.0f, -200, 200, -200, 200).build();
    const uint32_t w = 48, h = 27;
    const ReferenceImage image = renderReference(s, mesh, w, h);
    const ReferenceScene scene(s, mesh, w, h);
    int ground = 0, clippedGround = 0, sky = 0;
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const std::size_t i = std::size_t{y} * w + x;
            const glm::dvec3 eye = scene.camera().eye();
            const glm::dvec3 dir = scene.pixelRay(x, y).direction;
            const double cosAxis = glm::dot(dir, scene.camera().axis());
            const double toGround = dir.y < 0.0 ? -eye.y / dir.y : -1.0;
            double expectedS = 20.0 / cosAxis;
            if (toGround > 0.0 && toGround * cosAxis < 20.0 * (1.0 - 1e-6)) {
                expectedS = toGround;
                ++ground;
            } else if (toGround > 0.0 && toGround * cosAxis > 20.0 * (1.0 + 1e-6)) {
                ++clippedGround;
            } else if (toGround > 0.0) {
                continue;  // at the far plane itself: either answer is right
            } else {
                ++sky;
            }
            // The view matrix is float: its axis and camera-space z agree to about 1e-7.
            EXPECT_NEAR(image.distance[i], expectedS, 1e-6 * expectedS) << x << ", " << y;
            const ls::ref::Ray ray{eye, dir, image.distance[i]};
            const glm::dvec3 expected =
                ls::ref::directionalClosedForm(scene.medium(), scene.light(), ray);
            const glm::dvec3 actual(image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]);
            EXPECT_TRUE(near3(actual, expected, 1e-9 * maxAbs(expected))) << x << ", " << y;
            EXPECT_GT(actual.x, 0.0);
        }
    }
    EXPECT_GT(ground, 100);
    EXPECT_GT(clippedGround, 20);
    EXPECT_GT(sky, 100);
}

// One occluder's shadow volume against the whole image: for every pixel whose pieces are all longer
// than two sample spacings, the lit intervals equal [0, S] (or the spot's volume) without the
// analytic shadow interval to 1e-9 S, and Lin equals the model evaluated on the analytic intervals.
// Returns how many checked pixels had a shadow, so that a caller can insist on enough of them.
struct ShadowCase {
    host::SceneDesc scene;
    host::MeshData mesh;
    uint32_t width, height;
    ReferenceOptions options;
    // The occluder's shadow volume along a ray, as affine constraints.
    std::function<std::vector<Affine>(const ls::ref::Ray&)> shadow;
    double linTolerance;  // relative to the unshadowed Lin of the same ray
};

int checkShadowCase(const ShadowCase& c) {
    const ReferenceScene scene(c.scene, c.mesh, c.width, c.height, c.options);
    const ls::ref::Light& light = scene.light();
    ls::ref::QuadOptions quad;
    quad.relTol = 1e-11;
    int withShadow = 0;
    for (uint32_t y = 0; y < c.height; ++y) {
        for (uint32_t x = 0; x < c.width; ++x) {
            const ls::ref::Ray ray = scene.pixelRay(x, y);
            const double S = ray.length;
            const std::optional<Interval> shadow = solve(c.shadow(ray), S);
            const std::vector<Interval> volume = ls::ref::spotLitIntervals(light, ray);
            const std::vector<Interval> expected =
                ls::ref::intersectIntervals(volume, complement(shadow, S));
            std::vector<double> points{0.0, S};
            for (const Interval& in : volume) points.insert(points.end(), {in.begin, in.end});
            if (shadow) points.insert(points.end(), {shadow->begin, shadow->end});
            if (!resolvable(points, S / c.options.visibilitySamples)) continue;
            const bool shadowed = !sameIntervals(expected, volume, 0.0);
            withShadow += shadowed;

            EXPECT_TRUE(sameIntervals(scene.litIntervals(ray), expected, 1e-9 * S))
                << "pixel " << x << ", " << y;
            const glm::dvec3 unshadowed =
                light.type == ls::ref::Light::Directional
                    ? ls::ref::directionalClosedForm(scene.medium(), light, ray)
                    : ls::ref::integrateInscatter(scene.medium(), light, ray, quad).value;
            const glm::dvec3 model =
                light.type == ls::ref::Light::Directional
                    ? ls::ref::directionalClosedForm(scene.medium(), light, ray, expected)
                    : ls::ref::integrateInscatter(scene.medium(), light, ray, expected, quad).value;
            EXPECT_TRUE(near3(scene.inscatter(ray), model, c.linTolerance * maxAbs(unshadowed)))
                << "pixel " << x << ", " << y;
        }
    }
    return withShadow;
}

TEST(ReferenceRenderer, PlateShadowOfADirectionalLightIsItsSlab) {
    ShadowCase c;
    c.scene = baseScene();
    c.mesh = MeshBuilder()
                 .horizontal(0.0f, -200, 200, -200, 200)
                 .horizontal(1.0f, -1.0f, 1.0f, -1.0f, 1.0f)
                 .build();
    c.width = 48;
    c.height = 27;
    c.linTolerance = 1e-8;
    const glm::dvec3 d = glm::normalize(glm::dvec3(c.scene.light.direction));
    // P is in the plate's shadow iff it lies below the plate and the ray from P towards -d meets
    // the plate's plane inside the square, at Q.x = P.x + (1 - P.y) d.x / d.y (and the same for
    // z): every condition is affine in P, so along a view ray the shadow is one interval.
    c.shadow = [d](const ls::ref::Ray& r) {
        std::vector<Affine> out{{r.origin.y - 1.0, r.direction.y}};
        for (int axis : {0, 2}) {
            const double k = d[axis] / d.y;
            const double a = r.origin[axis] + (1.0 - r.origin.y) * k;
            const double b = r.direction[axis] - r.direction.y * k;
            out.push_back({a - 1.0, b});
            out.push_back({-a - 1.0, -b});
        }
        return out;
    };
    EXPECT_GT(checkShadowCase(c), 30);
}

// A point or spot light at (0, 4, 0) over a plate [-0.5, 0.5]^2 at y = 2: P is shadowed iff it lies
// below the plate and |P.x|, |P.z| <= (4 - P.y) / 4 (the pyramid from the light through the plate).
std::vector<Affine> pyramidShadow(const ls::ref::Ray& r) {
    std::vector<Affine> out{{r.origin.y - 2.0, r.direction.y}};
    for (int axis : {0, 2}) {
        for (double sign : {1.0, -1.0}) {
            out.push_back({sign * r.origin[axis] - 0.25 * (4.0 - r.origin.y),
                           sign * r.direction[axis] + 0.25 * r.direction.y});
        }
    }
    return out;
}

ShadowCase pyramidCase(lightscatter::LightType kind) {
    ShadowCase c;
    c.scene = baseScene();
    c.scene.camera.position = {0.3f, 1.0f, 6.0f};
    c.scene.camera.target = {0.0f, 0.8f, 0.0f};
    c.scene.light.type = kind;
    c.scene.light.position = {0.0f, 4.0f, 0.0f};
    c.scene.light.direction = {0.0f, -1.0f, 0.0f};
    c.scene.light.intensity = {30.0f, 20.0f, 10.0f};
    c.scene.light.innerConeAngleDegrees = c.scene.light.outerConeAngleDegrees = 35.0f;
    c.scene.light.range = 6.0f;
    c.scene.light.radius = 0.05f;
    c.mesh = MeshBuilder()
                 .horizontal(0.0f, -200, 200, -200, 200)
                 .horizontal(2.0f, -0.5f, 0.5f, -0.5f, 0.5f)
                 .build();
    c.width = 32;
    c.height = 18;
    c.options.relTol = 1e-11;
    c.linTolerance = 1e-7;
    c.shadow = pyramidShadow;
    return c;
}

TEST(ReferenceRenderer, PointLightOccluderShadowIsItsPyramid) {
    EXPECT_GT(checkShadowCase(pyramidCase(lightscatter::LightType::Point)), 20);
}

TEST(ReferenceRenderer, SpotLightOccluderShadowIsItsPyramidInsideTheCone) {
    EXPECT_GT(checkShadowCase(pyramidCase(lightscatter::LightType::Spot)), 20);
}

TEST(ReferenceRenderer, HandComputedRayThroughSpotConeAndShadow) {
    // A horizontal ray at y = 1 along +x from x = -5, 10 m long: the cone (35 degrees, apex 3 m
    // above) spans |x| <= 3 tan 35, the range (6 m) |x| <= sqrt(27), the plate's shadow |x| <=
    // 0.75.
    const ls::ref::Ray ray{{-5.0, 1.0, 0.0}, {1.0, 0.0, 0.0}, 10.0};
    const double cone = 3.0 * std::tan(glm::radians(35.0));
    ShadowCase spot = pyramidCase(lightscatter::LightType::Spot);
    const ReferenceScene spotScene(spot.scene, spot.mesh, 4, 4);
    EXPECT_TRUE(
        sameIntervals(spotScene.litIntervals(ray), {{5.0 - cone, 4.25}, {5.75, 5.0 + cone}}, 1e-8));
    ShadowCase point = pyramidCase(lightscatter::LightType::Point);
    const ReferenceScene pointScene(point.scene, point.mesh, 4, 4);
    EXPECT_TRUE(sameIntervals(pointScene.litIntervals(ray), {{0.0, 4.25}, {5.75, 10.0}}, 1e-8));
    // The range alone cuts the spot when the cone is wide: |x| <= sqrt(4^2 - 3^2).
    spot.scene.light.innerConeAngleDegrees = spot.scene.light.outerConeAngleDegrees = 80.0f;
    spot.scene.light.range = 4.0f;
    const ReferenceScene wide(spot.scene, spot.mesh, 4, 4);
    EXPECT_TRUE(sameIntervals(wide.litIntervals(ray),
                              {{5.0 - std::sqrt(7.0), 4.25}, {5.75, 5.0 + std::sqrt(7.0)}}, 1e-8));
    // Without shadows only the light's volume remains.
    point.options.shadows = false;
    const ReferenceScene unshadowed(point.scene, point.mesh, 4, 4, point.options);
    EXPECT_TRUE(sameIntervals(unshadowed.litIntervals(ray), {{0.0, 10.0}}, 0.0));
}

TEST(ReferenceRenderer, UnshadowedOptionKeepsOnlyTheLightVolume) {
    ShadowCase c = pyramidCase(lightscatter::LightType::Point);
    c.options.relTol = 1e-6;
    c.options.shadows = false;
    const ReferenceImage open = renderReference(c.scene, c.mesh, 16, 9, c.options);
    c.options.shadows = true;
    const ReferenceImage shadowed = renderReference(c.scene, c.mesh, 16, 9, c.options);
    int darker = 0;
    for (std::size_t i = 0; i < open.rgb.size(); ++i) {
        EXPECT_LE(shadowed.rgb[i], open.rgb[i] * (1.0 + 1e-9));
        darker += shadowed.rgb[i] < open.rgb[i] * 0.999;
    }
    EXPECT_GT(darker, 10);
    EXPECT_EQ(open.distance, shadowed.distance);
}

TEST(ReferenceRenderer, BackLitSurfaceShadowsTheMediumUpToItself) {
    // Light travelling upwards: the ground shades everything above it, right up to the surface at
    // each ray's end (no lit sliver where the shadow ray starts on the surface).
    host::SceneDesc s = baseScene();
    s.light.direction = {0.2f, 1.0f, 0.1f};
    const host::MeshData mesh = MeshBuilder().horizontal(0.0f, -2000, 2000, -2000, 2000).build();
    const ReferenceScene scene(s, mesh, 24, 14);
    int ground = 0;
    for (uint32_t y = 7; y < 14; ++y) {
        for (uint32_t x = 0; x < 24; ++x) {
            const ls::ref::Ray ray = scene.pixelRay(x, y);
            if (ray.direction.y >= -0.05) continue;
            ++ground;
            EXPECT_TRUE(scene.litIntervals(ray).empty()) << x << ", " << y;
            EXPECT_EQ(scene.inscatter(ray), glm::dvec3(0.0));
        }
    }
    EXPECT_GT(ground, 50);
}

TEST(ReferenceRenderer, SkyPixelsUseTheFarPlaneOrMaxDistance) {
    host::SceneDesc s = baseScene();
    s.camera.position = {0.0f, 0.0f, 0.0f};
    s.camera.target = {0.0f, 0.0f, -1.0f};
    // A wall 30 m ahead filling the view, and a small quad nearer than the near plane.
    const host::MeshData mesh =
        MeshBuilder()
            .quad({-100, -100, -30}, {100, -100, -30}, {100, 100, -30}, {-100, 100, -30})
            .quad({-1, -1, -0.05f}, {1, -1, -0.05f}, {1, 1, -0.05f}, {-1, 1, -0.05f})
            .build();
    const uint32_t w = 16, h = 9;
    // The near quad would shadow part of the medium; this test is about S only.
    ReferenceOptions options;
    options.shadows = false;
    auto check = [&](const char* what, float farPlane, bool infinite, bool reversed,
                     float maxDistance, auto expectedS) {
        s.camera.farPlane = farPlane;
        s.camera.infiniteFar = infinite;
        s.camera.reversedZ = reversed;
        s.medium.maxDistance = maxDistance;
        const ReferenceImage image = renderReference(s, mesh, w, h, options);
        const ReferenceScene scene(s, mesh, w, h, options);
        for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < w; ++x) {
                const glm::dvec3 dir = scene.pixelRay(x, y).direction;
                const double S = expectedS(-dir.z);  // -dir.z: cosine to the view axis
                const std::size_t i = std::size_t{y} * w + x;
                EXPECT_NEAR(image.distance[i], S, 1e-6 * S) << what << " pixel " << x << ", " << y;
                const glm::dvec3 lin = ls::ref::directionalClosedForm(
                    scene.medium(), scene.light(), {scene.camera().eye(), dir, image.distance[i]});
                EXPECT_TRUE(near3({image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]},
                                  lin, 1e-9 * maxAbs(lin)))
                    << what;
            }
        }
    };
    // The wall lies beyond the far plane: clipped, so sky at the far plane's distance ...
    check("far plane", 20.0f, false, false, 1000.0f, [](double c) { return 20.0 / c; });
    check("far plane, reversed", 20.0f, false, true, 1000.0f, [](double c) { return 20.0 / c; });
    // ... or at maxDistance where that is nearer.
    check("maxDistance", 20.0f, false, false, 15.0f, [](double) { return 15.0; });
    // A visible surface is never capped by maxDistance (and the quad before the near plane is
    // clipped, so every pixel sees the wall).
    check("surface", 100.0f, false, false, 15.0f, [](double c) { return 30.0 / c; });
    check("surface, infinite", 1.0f, true, true, 15.0f, [](double c) { return 30.0 / c; });
    // With an infinite far plane the sky ends at maxDistance.
    s.camera.target = {0.0f, 0.0f, 1.0f};  // looking away from the wall
    check("infinite far", 1.0f, true, false, 42.0f, [](double) { return 42.0; });
    check("infinite far, reversed", 1.0f, true, true, 42.0f, [](double) { return 42.0; });
}

// A scene of several lights is the sum of its lights' single renders, each shadowed by the plate
// through its own visibility (the sun's slab, the spot's and the point light's pyramids from
// different positions): no light is dropped, counted twice or shadowed from another's position.
TEST(ReferenceRenderer, SeveralLightsAreTheSumOfTheirSingleRenders) {
    ShadowCase c = pyramidCase(lightscatter::LightType::Spot);
    c.options.relTol = 1e-6;
    host::LightDesc sun = baseScene().light;
    host::LightDesc point = c.scene.light;
    point.type = lightscatter::LightType::Point;
    point.position = {1.5f, 3.0f, -0.5f};
    point.intensity = {5.0f, 8.0f, 12.0f};
    host::SceneDesc all = c.scene;
    all.moreLights = {sun, point};
    all.lightList = true;
    const uint32_t w = 20, h = 11;
    const ReferenceImage sum = renderReference(all, c.mesh, w, h, c.options);
    std::vector<double> expected(sum.rgb.size(), 0.0);
    for (std::size_t i = 0; i < all.lightCount(); ++i) {
        host::SceneDesc one = c.scene;
        one.light = all.lightAt(i);
        const ReferenceImage single = renderReference(one, c.mesh, w, h, c.options);
        ASSERT_GT(*std::max_element(single.rgb.begin(), single.rgb.end()), 0.0) << "light " << i;
        for (std::size_t k = 0; k < expected.size(); ++k) expected[k] += single.rgb[k];
    }
    for (std::size_t k = 0; k < expected.size(); ++k)
        EXPECT_NEAR(sum.rgb[k], expected[k], 1e-14 * expected[k]) << k;

    const ReferenceScene scene(all, c.mesh, w, h, c.options);
    ASSERT_EQ(scene.lights().size(), 3u);
    EXPECT_EQ(scene.lights()[1].type, ls::ref::Light::Directional);
    EXPECT_EQ(scene.lights()[2].position, glm::dvec3(1.5, 3.0, -0.5));
    // A vertical ray just under the plate's centre, down to the floor: the spot straight above
    // sees none of it; the point light at (1.5, 3, -0.5) sees the plate from aside, so its segment
    // to (0, y, 0) crosses y = 2 at x = 1.5 (2 - y) / (3 - y), inside the plate (x <= 0.5) only for
    // y >= 1.5. Lit for the point light: y from 1.5 down to the floor.
    const ls::ref::Ray down{{0.0, 1.999, 0.0}, {0.0, -1.0, 0.0}, 1.999};
    EXPECT_TRUE(scene.litIntervals(down, 0).empty());
    const std::vector<Interval> pointLit = scene.litIntervals(down, 2);
    ASSERT_EQ(pointLit.size(), 1u);
    EXPECT_NEAR(pointLit[0].begin, 1.999 - 1.5, 1e-8);
    EXPECT_NEAR(pointLit[0].end, 1.999, 1e-8);
}

// A spot's cookie: a uniform one scales the image by its sRGB-decoded value per channel, and one
// black on half of its image takes part of the light away and adds none.
TEST(ReferenceRenderer, ACookieColoursTheSpotByItsDecodedValue) {
    ShadowCase c = pyramidCase(lightscatter::LightType::Spot);
    c.options.relTol = 1e-8;
    const uint32_t w = 20, h = 11;
    const ReferenceImage plain = renderReference(c.scene, c.mesh, w, h, c.options);
    auto cookie = std::make_shared<host::Texture>();
    cookie->width = cookie->height = 8;
    cookie->rgba.assign(8 * 8 * 4, 255);
    for (std::size_t t = 0; t < 64; ++t) {
        cookie->rgba[4 * t] = 188;  // 0.5 once decoded (0.50289)
        cookie->rgba[4 * t + 1] = 255;
        cookie->rgba[4 * t + 2] = 64;  // 0.0513
    }
    host::SceneDesc coloured = c.scene;
    coloured.light.cookie = cookie;
    const ReferenceImage tinted = renderReference(coloured, c.mesh, w, h, c.options);
    const double red = std::pow((188.0 / 255.0 + 0.055) / 1.055, 2.4),
                 blue = std::pow((64.0 / 255.0 + 0.055) / 1.055, 2.4);
    double lit = 0;
    for (std::size_t k = 0; k < plain.rgb.size(); k += 3) {
        EXPECT_NEAR(tinted.rgb[k], red * plain.rgb[k], 1e-6 * plain.rgb[k] + 1e-15) << k;
        EXPECT_NEAR(tinted.rgb[k + 1], plain.rgb[k + 1], 1e-6 * plain.rgb[k + 1] + 1e-15) << k;
        EXPECT_NEAR(tinted.rgb[k + 2], blue * plain.rgb[k + 2], 1e-6 * plain.rgb[k + 2] + 1e-15)
            << k;
        lit += plain.rgb[k + 1];
    }
    EXPECT_GT(lit, 0.0);

    // Half black: darker than the plain image, brighter than nothing, nowhere brighter.
    auto half = std::make_shared<host::Texture>(*cookie);
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 8; ++x)
            for (int k = 0; k < 3; ++k)
                half->rgba[(y * 8 + x) * 4 + static_cast<uint32_t>(k)] = x < 4 ? 0 : 255;
    coloured.light.cookie = half;
    const ReferenceImage halved = renderReference(coloured, c.mesh, w, h, c.options);
    double sumHalf = 0, sumPlain = 0;
    for (std::size_t k = 0; k < plain.rgb.size(); ++k) {
        EXPECT_LE(halved.rgb[k], plain.rgb[k] * (1.0 + 1e-6) + 1e-15) << k;
        sumHalf += halved.rgb[k];
        sumPlain += plain.rgb[k];
    }
    std::printf("half-black cookie: %.3f of the plain spot's light\n", sumHalf / sumPlain);
    EXPECT_GT(sumHalf, 0.2 * sumPlain);
    EXPECT_LT(sumHalf, 0.8 * sumPlain);
}

// Both images within rel of each other per value (absolute floor: 1e-12 of the largest).
void expectSameImage(const ReferenceImage& a, const ReferenceImage& b, double rel) {
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    const double largest = *std::max_element(a.rgb.begin(), a.rgb.end());
    for (std::size_t i = 0; i < a.rgb.size(); ++i) {
        EXPECT_NEAR(a.rgb[i], b.rgb[i], rel * std::abs(a.rgb[i]) + 1e-12 * largest) << i;
    }
    for (std::size_t i = 0; i < a.distance.size(); ++i) {
        EXPECT_NEAR(a.distance[i], b.distance[i], 1e-12 * a.distance[i]) << i;
    }
}

TEST(ReferenceRenderer, DepthConventionDoesNotChangeTheImage) {
    for (const lightscatter::LightType kind :
         {lightscatter::LightType::Directional, lightscatter::LightType::Spot}) {
        ShadowCase c = pyramidCase(kind);
        c.options.relTol = 1e-9;
        c.scene.camera.farPlane = 500.0f;  // every surface inside it
        const ReferenceImage standard = renderReference(c.scene, c.mesh, 24, 14, c.options);
        for (const auto& [reversed, infinite] :
             {std::pair{true, false}, {false, true}, {true, true}}) {
            c.scene.camera.reversedZ = reversed;
            c.scene.camera.infiniteFar = infinite;
            const ReferenceImage other = renderReference(c.scene, c.mesh, 24, 14, c.options);
            SCOPED_TRACE(std::string(reversed ? "reversed" : "standard") +
                         (infinite ? ", infinite" : ""));
            expectSameImage(standard, other, 1e-8);
        }
    }
}

TEST(ReferenceRenderer, ThreadCountDoesNotChangeTheImage) {
    ShadowCase c = pyramidCase(lightscatter::LightType::Spot);
    c.options.relTol = 1e-6;
    c.options.threads = 1;
    const ReferenceImage one = renderReference(c.scene, c.mesh, 20, 11, c.options);
    for (uint32_t threads : {2u, 3u, 7u, 0u}) {
        c.options.threads = threads;
        const ReferenceImage many = renderReference(c.scene, c.mesh, 20, 11, c.options);
        ASSERT_EQ(many.rgb.size(), one.rgb.size());
        EXPECT_EQ(std::memcmp(many.rgb.data(), one.rgb.data(), one.rgb.size() * sizeof(double)), 0)
            << threads << " threads";
        EXPECT_EQ(std::memcmp(many.distance.data(), one.distance.data(),
                              one.distance.size() * sizeof(double)),
                  0);
    }
    EXPECT_GT(*std::max_element(one.rgb.begin(), one.rgb.end()), 0.0);
}

// Embree only traverses; every candidate is decided by the same double test, so the image is the
// own traversal's bit for bit: on the occluder cases of every light type and on shipped scenes
// (a room lit through a window, the atrium's columns, a point light in fog, and the 121k-triangle
// engine under a spot).
TEST(ReferenceRenderer, EmbreeTraversalGivesTheSameImageBitForBit) {
    auto same = [](const host::SceneDesc& scene, const host::MeshData& mesh, uint32_t w, uint32_t h,
                   ReferenceOptions options, const std::string& what) {
        options.traversal = host::reference::Bvh::Traversal::Own;
        const ReferenceImage own = renderReference(scene, mesh, w, h, options);
        options.traversal = host::reference::Bvh::Traversal::Embree;
        const ReferenceImage embree = renderReference(scene, mesh, w, h, options);
        ASSERT_EQ(own.rgb.size(), embree.rgb.size()) << what;
        EXPECT_EQ(std::memcmp(own.rgb.data(), embree.rgb.data(), own.rgb.size() * sizeof(double)),
                  0)
            << what;
        EXPECT_GT(*std::max_element(own.rgb.begin(), own.rgb.end()), 0.0) << what;
    };
    for (lightscatter::LightType type :
         {lightscatter::LightType::Directional, lightscatter::LightType::Spot,
          lightscatter::LightType::Point}) {
        const ShadowCase c = pyramidCase(type);
        same(c.scene, c.mesh, 24, 14, c.options, "pyramid case " + std::to_string(int(type)));
    }
    for (const char* name : {"window_room", "atrium", "point_fog", "engine_spot"}) {
        const host::SceneDesc scene =
            host::loadSceneFile(std::string(LS_SOURCE_DIR) + "/scenes/" + name + ".json");
        same(scene, host::loadSceneMeshes(scene), 32, 18, {}, name);
    }
}

TEST(ReferenceRenderer, ProgressRisesToOne) {
    ShadowCase c = pyramidCase(lightscatter::LightType::Directional);
    c.options.threads = 3;
    std::vector<double> seen;
    const ReferenceImage image =
        renderReference(c.scene, c.mesh, 12, 10, c.options, [&](double f) { seen.push_back(f); });
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.back(), 1.0);
    EXPECT_EQ(seen.size(), 10u);  // once per row
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_GT(seen.front(), 0.0);
    EXPECT_EQ(image.width, 12u);
    EXPECT_EQ(image.height, 10u);
    EXPECT_EQ(image.rgb.size(), 12u * 10u * 3u);
    EXPECT_EQ(image.distance.size(), 12u * 10u);

    seen.clear();
    const ReferenceImage empty =
        renderReference(c.scene, c.mesh, 0, 0, c.options, [&](double f) { seen.push_back(f); });
    EXPECT_TRUE(empty.rgb.empty());
    EXPECT_EQ(seen, std::vector<double>{1.0});
}

// docs/model.md's non-uniform medium: a homogeneous density folds into the coefficients as the
// plugin folds it (a float product), and height fog and volumes become the model's Density.
TEST(ReferenceRenderer, ConvertsTheMediumsDensity) {
    host::MediumDesc m;
    m.betaR = {0.1f, 0.2f, 0.3f};
    m.betaM = {0.01f, 0.02f, 0.03f};
    m.sigmaA = {0.5f, 0.25f, 0.125f};
    m.density = 0.3f;
    const ls::ref::Medium folded = host::reference::toReferenceMedium(m);
    EXPECT_TRUE(folded.density.unit());
    EXPECT_EQ(folded.betaR, glm::dvec3(m.betaR * 0.3f));
    EXPECT_EQ(folded.betaM, glm::dvec3(m.betaM * 0.3f));
    EXPECT_EQ(folded.sigmaA, glm::dvec3(m.sigmaA * 0.3f));

    m.heightFog = lightscatter::HeightFog{2.0f, 0.5f};
    lightscatter::FogVolume v;
    v.center = {1.0f, 2.0f, 3.0f};
    v.halfExtents = {4.0f, 5.0f, 6.0f};
    v.axes = {{{0.0f, 0.0f, 1.0f}, {0.0f, 1.0005f, 0.0f}, {-1.0f, 0.0f, 0.0f}}};
    v.density = 2.5f;
    v.fade = 0.75f;
    m.fogVolumes.push_back(v);
    const ls::ref::Medium fog = host::reference::toReferenceMedium(m);
    EXPECT_EQ(fog.betaR, glm::dvec3(m.betaR));  // m(x) multiplies them: nothing folded
    EXPECT_EQ(fog.density.base, static_cast<double>(0.3f));
    ASSERT_TRUE(fog.density.heightFog.has_value());
    EXPECT_EQ(fog.density.heightFog->baseHeight, 2.0);
    EXPECT_EQ(fog.density.heightFog->falloff, 0.5);
    ASSERT_EQ(fog.density.volumes.size(), 1u);
    const ls::ref::FogBox& box = fog.density.volumes[0];
    EXPECT_EQ(box.center, glm::dvec3(1, 2, 3));
    EXPECT_EQ(box.halfExtents, glm::dvec3(4, 5, 6));
    EXPECT_EQ(box.axes[0], glm::dvec3(0, 0, 1));
    // The plugin accepts axes within 1e-3 of unit length and normalises them; so does the model.
    EXPECT_NEAR(glm::length(box.axes[1] - glm::dvec3(0, 1, 0)), 0.0, 1e-15);
    EXPECT_EQ(box.density, 2.5);
    EXPECT_EQ(box.fade, 0.75);
}

// The pyramid case's medium as height fog, with a faded fog box around part of the spot's beam.
host::SceneDesc foggy(host::SceneDesc s) {
    s.medium.density = 0.5f;
    s.medium.heightFog = lightscatter::HeightFog{0.5f, 1.2f};
    lightscatter::FogVolume v;
    v.center = {0.3f, 1.0f, 0.5f};
    v.halfExtents = {1.0f, 0.8f, 1.2f};
    v.density = 6.0f;
    v.fade = 0.4f;
    s.medium.fogVolumes.push_back(v);
    return s;
}

// A cookie's factor rides on the medium's integrand: a uniform cookie scales the foggy image by its
// decoded value, as it does the homogeneous one, and the fog changes the image well beyond that.
TEST(ReferenceRenderer, ACookieColoursTheSpotInANonUniformMediumToo) {
    ShadowCase c = pyramidCase(lightscatter::LightType::Spot);
    c.options.relTol = 1e-8;
    const uint32_t w = 16, h = 9;
    const host::SceneDesc fog = foggy(c.scene);
    const ReferenceImage homogeneous = renderReference(c.scene, c.mesh, w, h, c.options);
    const ReferenceImage plain = renderReference(fog, c.mesh, w, h, c.options);
    auto cookie = std::make_shared<host::Texture>();
    cookie->width = cookie->height = 4;
    cookie->rgba.assign(4 * 4 * 4, 255);
    for (std::size_t t = 0; t < 16; ++t) cookie->rgba[4 * t] = 188;  // 0.50289 once decoded
    host::SceneDesc coloured = fog;
    coloured.light.cookie = cookie;
    const ReferenceImage tinted = renderReference(coloured, c.mesh, w, h, c.options);
    const double red = std::pow((188.0 / 255.0 + 0.055) / 1.055, 2.4);
    double changed = 0.0, lit = 0.0;
    for (std::size_t k = 0; k < plain.rgb.size(); k += 3) {
        EXPECT_NEAR(tinted.rgb[k], red * plain.rgb[k], 1e-6 * plain.rgb[k] + 1e-15) << k;
        EXPECT_NEAR(tinted.rgb[k + 1], plain.rgb[k + 1], 1e-6 * plain.rgb[k + 1] + 1e-15) << k;
        changed += std::abs(plain.rgb[k + 1] - homogeneous.rgb[k + 1]);
        lit += homogeneous.rgb[k + 1];
    }
    EXPECT_GT(lit, 0.0);
    EXPECT_GT(changed, 0.1 * lit);
}

// T(S) for the composite: exp(-betaT tau(S)) of the medium along each pixel's ray, exp(-betaT S)
// in a homogeneous one.
TEST(ReferenceRenderer, TransmittanceIsExpOfTheRaysOpticalDepth) {
    const ShadowCase c = pyramidCase(lightscatter::LightType::Spot);
    const ReferenceScene homogeneous(c.scene, c.mesh, 8, 6, c.options);
    const ReferenceScene fog(foggy(c.scene), c.mesh, 8, 6, c.options);
    for (uint32_t y = 0; y < 6; ++y) {
        for (uint32_t x = 0; x < 8; ++x) {
            const ls::ref::Ray ray = fog.pixelRay(x, y);
            const glm::dvec3 beta = fog.medium().betaT();
            EXPECT_EQ(homogeneous.transmittance(ray), glm::exp(-beta * ray.length));
            const double tau = ls::ref::opticalDepth(fog.medium().density, ray, 0.0, ray.length);
            EXPECT_TRUE(near3(fog.transmittance(ray), glm::exp(-beta * tau), 1e-15));
            EXPECT_GT(tau, 0.0);
        }
    }
}

}  // namespace
