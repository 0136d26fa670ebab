// The directional shadow box: as deep as the scene, and across the light only as wide as the part
// of the scene the camera sees. A far-away model outside the view used to stretch the box over it
// and leave a few texels for the room the camera looks at. A box the view cannot give (nothing
// seen, or nothing a float resolves) is the scene's.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>
#include <random>
#include <vector>

#include "camera_math.h"

namespace {

glm::vec3 toClip(const glm::mat4& m, const glm::vec3& p) {
    const glm::vec4 c = m * glm::vec4(p, 1.0f);
    return glm::vec3(c) / c.w;
}

host::LightDesc sun() {
    host::LightDesc l;
    l.type = lightscatter::LightType::Directional;
    l.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    return l;
}

host::CameraDesc roomCamera() {
    host::CameraDesc c;
    c.position = {0.0f, 1.7f, 4.0f};
    c.target = {0.0f, 1.0f, 0.0f};
    c.farPlane = 100000.0f;
    return c;
}

}  // namespace

TEST(ShadowFit, AFarAwayModelOutsideTheViewDoesNotWidenTheSunsBox) {
    host::Bounds room;
    room.add({-5.0f, 0.0f, -5.0f});
    room.add({5.0f, 4.0f, 5.0f});
    host::Bounds withFarModel = room;
    withFarModel.add({9000.0f, 0.0f, 9000.0f});  // behind the camera's back, 12 km away
    withFarModel.add({9010.0f, 30.0f, 9010.0f});

    const float aspect = 16.0f / 9.0f;
    host::Bounds farModel;
    farModel.add({9000.0f, 0.0f, 9000.0f});
    farModel.add({9010.0f, 30.0f, 9010.0f});
    const glm::mat4 near = host::shadowViewProjection(sun(), room, {room}, roomCamera(), aspect);
    const glm::mat4 far =
        host::shadowViewProjection(sun(), withFarModel, {room, farModel}, roomCamera(), aspect);
    // One metre across the room covers about as many texels with or without the far model.
    const glm::vec3 a = toClip(far, {0.0f, 0.0f, 0.0f}), b = toClip(far, {1.0f, 0.0f, 0.0f});
    const glm::vec3 a0 = toClip(near, {0.0f, 0.0f, 0.0f}), b0 = toClip(near, {1.0f, 0.0f, 0.0f});
    const float withModel = glm::length(glm::vec2(b - a)),
                without = glm::length(glm::vec2(b0 - a0));
    EXPECT_GT(withModel, 0.5f * without)
        << "the far model shrank the room to " << withModel / without << " of its texels";
    // Every point of the room the camera sees is inside the map, in depth too.
    const glm::mat4 camera =
        host::cameraProjection(roomCamera(), aspect) * host::cameraView(roomCamera());
    int seen = 0;
    for (float x = -5.0f; x <= 5.0f; x += 0.5f)
        for (float y = 0.0f; y <= 4.0f; y += 0.5f)
            for (float z = -5.0f; z <= 5.0f; z += 0.5f) {
                const glm::vec4 v = camera * glm::vec4(x, y, z, 1.0f);
                if (v.w <= 0.0f || std::abs(v.x) > v.w || std::abs(v.y) > v.w) continue;
                ++seen;
                for (const glm::mat4& m : {near, far}) {
                    const glm::vec3 c = toClip(m, {x, y, z});
                    ASSERT_LE(std::abs(c.x), 1.0f) << x << " " << y << " " << z;
                    ASSERT_LE(std::abs(c.y), 1.0f) << x << " " << y << " " << z;
                    ASSERT_GE(c.z, 0.0f);
                    ASSERT_LE(c.z, 1.0f);
                }
            }
    EXPECT_GT(seen, 100);
    // The far model still lies within the box's depth range: it casts where it stands.
    const glm::vec3 f = toClip(far, {9005.0f, 30.0f, 9005.0f});
    EXPECT_GE(f.z, 0.0f);
    EXPECT_LE(f.z, 1.0f);
}

TEST(ShadowFit, TheWholeSceneInViewKeepsTheWholeSceneInTheMap) {
    host::Bounds scene;
    scene.add({-50.0f, 0.0f, -50.0f});
    scene.add({50.0f, 20.0f, 50.0f});
    host::CameraDesc c;
    c.position = {0.0f, 150.0f, 150.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.fovYDegrees = 70.0f;
    const glm::mat4 m = host::shadowViewProjection(sun(), scene, {}, c, 1.0f);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p((i & 1) ? 50.0f : -50.0f, (i & 2) ? 20.0f : 0.0f,
                          (i & 4) ? 50.0f : -50.0f);
        const glm::vec3 clip = toClip(m, p);
        EXPECT_LE(std::abs(clip.x), 1.0f) << i;
        EXPECT_LE(std::abs(clip.y), 1.0f) << i;
        EXPECT_GE(clip.z, 0.0f) << i;
        EXPECT_LE(clip.z, 1.0f) << i;
    }
}

namespace {

// How far from singular a world -> clip matrix is, as the plugin judges it (matrix_checks.cpp):
// |det| over the product of its rows' lengths, about the centre of its clip volume.
double centredConditioning(const glm::mat4& m) {
    const glm::dmat4 d(m);
    const double det = glm::determinant(d);
    if (!(std::fabs(det) > 0.0) || !std::isfinite(det)) return 0.0;
    const glm::dvec4 c = glm::inverse(d) * glm::dvec4(0.0, 0.0, 0.5, 1.0);
    glm::dmat4 centred(1.0);
    centred[3] = glm::dvec4(glm::dvec3(c) / c.w, 1.0);
    const glm::dmat4 e = d * centred;
    double rows = 1.0;
    for (int r = 0; r < 4; ++r) rows *= glm::length(glm::dvec4(e[0][r], e[1][r], e[2][r], e[3][r]));
    return rows > 0.0 ? std::fabs(glm::determinant(e)) / rows : 0.0;
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// Points of `parts` the camera sees (inside its frustum, between its planes), `perPart` random
// ones each, and how many of them the shadow map `m` leaves out.
struct Coverage {
    int seen = 0, outside = 0;
};
Coverage coverage(const glm::mat4& m, const std::vector<host::Bounds>& parts,
                  const host::CameraDesc& c, float aspect, uint32_t seed, int perPart = 200) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const glm::mat4 view = host::cameraView(c), camera = host::cameraProjection(c, aspect) * view;
    Coverage k;
    for (const host::Bounds& b : parts)
        for (int i = 0; i < perPart; ++i) {
            const glm::vec3 p = b.min + (b.max - b.min) * glm::vec3(u(rng), u(rng), u(rng));
            const glm::vec4 v = camera * glm::vec4(p, 1.0f);
            const float depth = -(view * glm::vec4(p, 1.0f)).z;
            if (v.w <= 0.0f || std::fabs(v.x) > v.w || std::fabs(v.y) > v.w || depth < c.nearPlane)
                continue;
            if (!c.infiniteFar && depth > c.farPlane) continue;
            ++k.seen;
            const glm::vec3 q = toClip(m, p);
            if (!(std::fabs(q.x) <= 1.0001f && std::fabs(q.y) <= 1.0001f && q.z >= -1e-4f &&
                  q.z <= 1.0001f))
                ++k.outside;
        }
    return k;
}

host::LightDesc sunAt(float elevationDegrees, float azimuthDegrees) {
    const float e = glm::radians(elevationDegrees), a = glm::radians(azimuthDegrees);
    host::LightDesc l;
    l.type = lightscatter::LightType::Directional;
    l.direction = {std::cos(e) * std::sin(a), -std::sin(e), std::cos(e) * std::cos(a)};
    return l;
}

}  // namespace

// scenes/hard/low_sun_city: a sun 3 degrees above the horizon over a city 20 km deep, seen along
// its avenue with reversed depth. The view-fitted box lies off the world's origin by far more than
// its size, which the plugin took for a singular matrix (issue #22): it is an ordinary box, holds
// everything the camera sees, and is no wider than the scene's.
TEST(ShadowFit, ALowSunOverACityAlongA20KmViewGivesAUsableBox) {
    std::vector<host::Bounds> parts(1);
    parts[0].add({-1000.0f, 0.0f, -20500.0f});  // the ground
    parts[0].add({1000.0f, 0.0f, 500.0f});
    host::Bounds scene = parts[0];
    for (int row = 0; row < 24; ++row)
        for (int column = 0; column < 6; ++column) {
            const float x = (float(column) - 2.5f) * 300.0f + (column < 3 ? -60.0f : 60.0f);
            const float z = -400.0f - 800.0f * float(row),
                        h = 10.0f + 140.0f * float((row * 7 + column * 3) % 10) / 9.0f;
            host::Bounds b;
            b.add({x - 90.0f, 0.0f, z - 250.0f});
            b.add({x + 90.0f, h, z + 250.0f});
            parts.push_back(b);
            scene.add(b.min);
            scene.add(b.max);
        }
    host::CameraDesc c;
    c.position = {0.0f, 40.0f, 300.0f};
    c.target = {0.0f, 25.0f, -20000.0f};
    c.nearPlane = 0.5f;
    c.farPlane = 20000.0f;
    c.reversedZ = true;
    const float aspect = 16.0f / 9.0f;
    const glm::mat4 m = host::shadowViewProjection(sunAt(3.0f, 60.0f), scene, parts, c, aspect);
    ASSERT_TRUE(finite(m));
    EXPECT_GT(centredConditioning(m), 1e-6);
    const Coverage k = coverage(m, parts, c, aspect, 1);
    EXPECT_GT(k.seen, 1000);
    EXPECT_EQ(k.outside, 0) << "of " << k.seen;
    // The fit only narrows: a metre of the scene covers at least the texels the scene's box gives
    // it.
    const glm::mat4 whole = host::shadowViewProjection(sunAt(3.0f, 60.0f), scene, {}, c, aspect);
    const glm::vec3 a = toClip(m, {0.0f, 0.0f, -1000.0f}), b = toClip(m, {1.0f, 0.0f, -1000.0f});
    const glm::vec3 a0 = toClip(whole, {0.0f, 0.0f, -1000.0f}),
                    b0 = toClip(whole, {1.0f, 0.0f, -1000.0f});
    EXPECT_GE(glm::length(glm::vec2(b - a)), 0.99f * glm::length(glm::vec2(b0 - a0)));
}

// A part of no width in the light's view (a single point, or a flat part the sun grazes) used to
// be dropped from the fit, and what the camera saw of it fell outside the map.
TEST(ShadowFit, APartOfNoWidthInViewIsInTheMap) {
    host::Bounds room, point, floor;
    room.add({-5.0f, 0.0f, -5.0f});
    room.add({5.0f, 4.0f, -3.0f});
    point.add({2.0f, 0.0f, 1.0f});
    floor.add({-5.0f, 0.0f, 0.0f});
    floor.add({5.0f, 0.0f, 3.0f});
    host::Bounds scene = room;
    for (const host::Bounds& b : {point, floor}) {
        scene.add(b.min);
        scene.add(b.max);
    }
    host::CameraDesc c = roomCamera();
    c.position = {0.0f, 1.7f, 6.0f};
    c.target = {0.0f, 0.5f, 0.0f};
    for (const host::LightDesc& l : {sunAt(0.0f, 90.0f), sunAt(35.0f, 20.0f)}) {
        const glm::mat4 m = host::shadowViewProjection(l, scene, {room, point, floor}, c, 1.5f);
        ASSERT_TRUE(finite(m));
        const glm::vec3 p = toClip(m, {2.0f, 0.0f, 1.0f});
        EXPECT_LE(std::fabs(p.x), 1.0f);
        EXPECT_LE(std::fabs(p.y), 1.0f);
        const Coverage k = coverage(m, {room, point, floor}, c, 1.5f, 2);
        EXPECT_GT(k.seen, 100);
        EXPECT_EQ(k.outside, 0) << "of " << k.seen;
    }
}

// A scene of one point 100 km from the origin: its box had no extent a float resolves, and the
// light's eye stood where its centre was, so the matrix was NaN.
TEST(ShadowFit, ASceneOfOnePointFarAwayGetsAFiniteBox) {
    host::Bounds point;
    point.add({90000.0f, 0.0f, -80000.0f});
    host::CameraDesc c;
    c.position = {89990.0f, 10.0f, -79990.0f};
    c.target = {90000.0f, 0.0f, -80000.0f};
    const glm::mat4 m = host::shadowViewProjection(sunAt(10.0f, 30.0f), point, {point}, c, 1.5f);
    ASSERT_TRUE(finite(m));
    EXPECT_GT(centredConditioning(m), 1e-6);
    const glm::vec3 p = toClip(m, point.min);
    EXPECT_LE(std::fabs(p.x), 1.0f);
    EXPECT_LE(std::fabs(p.y), 1.0f);
    EXPECT_GE(p.z, 0.0f);
    EXPECT_LE(p.z, 1.0f);
}

// Random scenes (up to 30 km across and 100 km from the origin, with flat parts and parts of one
// point), suns from the horizon to the zenith and cameras of every depth convention: every fit is
// finite, far from singular, and holds what the camera sees.
TEST(ShadowFit, RandomScenesSunsAndCamerasKeepWhatTheCameraSeesInTheMap) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int failures = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const float size = std::pow(10.0f, 1.0f + 3.5f * u(rng));
        const glm::vec3 offset =
            u(rng) < 0.3f ? glm::vec3((u(rng) - 0.5f) * 2e5f, 0.0f, (u(rng) - 0.5f) * 2e5f)
                          : glm::vec3(0.0f);
        std::vector<host::Bounds> parts;
        host::Bounds scene;
        const int n = 1 + int(20.0f * u(rng));
        for (int i = 0; i < n; ++i) {
            const glm::vec3 centre =
                offset + glm::vec3((u(rng) - 0.5f) * size, 0.0f, (u(rng) - 0.5f) * size);
            glm::vec3 h(size * 0.05f * u(rng), size * 0.04f * u(rng), size * 0.05f * u(rng));
            if (u(rng) < 0.2f) h.y = 0.0f;            // flat
            if (u(rng) < 0.05f) h = glm::vec3(0.0f);  // one point
            host::Bounds b;
            b.add(centre - glm::vec3(h.x, 0.0f, h.z));
            b.add(centre + h);
            parts.push_back(b);
            scene.add(b.min);
            scene.add(b.max);
        }
        const float pick = u(rng);
        const float elevation = pick < 0.1f   ? 0.0f
                                : pick < 0.2f ? 90.0f
                                              : 0.5f + 89.0f * u(rng) * u(rng);
        const host::LightDesc sun = sunAt(elevation, 360.0f * u(rng));
        host::CameraDesc c;
        c.position = offset + glm::vec3((u(rng) - 0.5f) * size, 1.0f + size * 0.05f * u(rng),
                                        (u(rng) - 0.5f) * size);
        const float heading = 6.2832f * u(rng);
        c.target = c.position + (u(rng) < 0.15f ? glm::vec3(0.001f, -1.0f, 0.0f)
                                                : glm::vec3(std::sin(heading), -0.3f * u(rng),
                                                            std::cos(heading)));
        c.fovYDegrees = u(rng) < 0.1f ? 170.0f : 10.0f + 100.0f * u(rng);
        c.nearPlane = u(rng) < 0.3f ? 1e-8f : 0.1f;
        c.farPlane = std::max(size * 2.0f * u(rng), 1.0f);
        c.reversedZ = c.nearPlane < 1e-3f || u(rng) < 0.5f;
        c.infiniteFar = u(rng) < 0.3f;
        const float aspect = 0.5f + 2.0f * u(rng);
        const glm::mat4 m = host::shadowViewProjection(sun, scene, parts, c, aspect);
        const bool ok = finite(m) && centredConditioning(m) > 1e-6 &&
                        coverage(m, parts, c, aspect, uint32_t(trial), 20).outside == 0;
        if (!ok && ++failures <= 5)
            ADD_FAILURE() << "trial " << trial << ": scene " << size << " m across, "
                          << glm::length(offset) << " m from the origin, sun at " << elevation
                          << " degrees";
    }
    EXPECT_EQ(failures, 0);
}
