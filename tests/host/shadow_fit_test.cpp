// The directional shadow box: as deep as the scene, and across the light only as wide as the part
// of the scene the camera sees. A far-away model outside the view used to stretch the box over it
// and leave a few texels for the room the camera looks at.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>

#include "camera_math.h"

namespace {

glm::vec3 toClip(const glm::mat4& m, const glm::vec3& p) {
    const glm::vec4 c = m * glm::vec4(p, 1.0f);
    return glm::vec3(c) / c.w;
}

host::LightDesc sun() {
    host::LightDesc l;
    l.type = host::LightKind::Directional;
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
    const glm::mat4 far = host::shadowViewProjection(sun(), withFarModel, {room, farModel}, roomCamera(), aspect);
    // One metre across the room covers about as many texels with or without the far model.
    const glm::vec3 a = toClip(far, {0.0f, 0.0f, 0.0f}), b = toClip(far, {1.0f, 0.0f, 0.0f});
    const glm::vec3 a0 = toClip(near, {0.0f, 0.0f, 0.0f}), b0 = toClip(near, {1.0f, 0.0f, 0.0f});
    const float withModel = glm::length(glm::vec2(b - a)), without = glm::length(glm::vec2(b0 - a0));
    EXPECT_GT(withModel, 0.5f * without) << "the far model shrank the room to " << withModel / without
                                          << " of its texels";
    // Every point of the room the camera sees is inside the map, in depth too.
    const glm::mat4 camera = host::cameraProjection(roomCamera(), aspect) * host::cameraView(roomCamera());
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
        const glm::vec3 p((i & 1) ? 50.0f : -50.0f, (i & 2) ? 20.0f : 0.0f, (i & 4) ? 50.0f : -50.0f);
        const glm::vec3 clip = toClip(m, p);
        EXPECT_LE(std::abs(clip.x), 1.0f) << i;
        EXPECT_LE(std::abs(clip.y), 1.0f) << i;
        EXPECT_GE(clip.z, 0.0f) << i;
        EXPECT_LE(clip.z, 1.0f) << i;
    }
}
