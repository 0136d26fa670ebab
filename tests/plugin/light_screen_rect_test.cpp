// The light's screen rectangle (ls::lightScreenRect), which the per-pixel marches draw within:
// every pixel whose view ray crosses the light's volume lies inside it (found by walking each
// pixel's ray through the volume in fine steps), and a small light's rectangle is small.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "shared/view_reach.h"

namespace {

ls::CameraParams camera(glm::vec3 eye, glm::vec3 target, VkExtent2D screen) {
    ls::CameraParams c;
    c.view = glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
    c.projection = glm::perspective(
        glm::radians(60.0f), static_cast<float>(screen.width) / static_cast<float>(screen.height),
        0.1f, 200.0f);
    c.projection[1][1] *= -1.0f;  // Vulkan's clip space: y down
    c.nearPlane = 0.1f;
    c.farPlane = 200.0f;
    return c;
}

ls::LightParams spot(glm::vec3 at, glm::vec3 direction, float outerDegrees, float range) {
    ls::LightParams l;
    l.kind = ls::LightType::Spot;
    l.position = at;
    l.direction = glm::normalize(direction);
    l.cosOuter = l.cosInner = std::cos(glm::radians(outerDegrees));
    l.range = range;
    return l;
}

bool inVolume(const ls::LightParams& l, glm::vec3 p) {
    const glm::vec3 d = p - l.position;
    const float r = glm::length(d);
    if (r > l.range) return false;
    return l.kind == ls::LightType::Point || glm::dot(d, l.direction) >= l.cosOuter * r;
}

// Pixels whose ray crosses the volume, and how many of them fall outside the rectangle.
struct Coverage {
    int reached = 0, outside = 0;
};
Coverage coverage(const ls::CameraParams& c, const ls::LightParams& l, VkExtent2D screen,
                  const VkRect2D& rect) {
    const glm::mat4 inverse = glm::inverse(c.projection * c.view);
    const glm::vec3 eye = glm::vec3(glm::inverse(c.view)[3]);
    Coverage out;
    for (uint32_t y = 0; y < screen.height; ++y)
        for (uint32_t x = 0; x < screen.width; ++x) {
            const glm::vec2 ndc(
                (static_cast<float>(x) + 0.5f) / static_cast<float>(screen.width) * 2.0f - 1.0f,
                (static_cast<float>(y) + 0.5f) / static_cast<float>(screen.height) * 2.0f - 1.0f);
            const glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
            const glm::vec3 dir = glm::normalize(glm::vec3(farPoint) / farPoint.w - eye);
            bool hit = false;
            for (float t = 0.0f; t < 60.0f && !hit; t += 0.02f) hit = inVolume(l, eye + t * dir);
            if (!hit) continue;
            ++out.reached;
            const bool inside =
                static_cast<int32_t>(x) >= rect.offset.x && x < rect.offset.x + rect.extent.width &&
                static_cast<int32_t>(y) >= rect.offset.y && y < rect.offset.y + rect.extent.height;
            if (!inside) ++out.outside;
        }
    return out;
}

TEST(LightScreenRect, HoldsEveryPixelTheLightReaches) {
    const VkExtent2D screen{96, 54};
    const ls::MediumParams medium;
    struct Case {
        const char* what;
        ls::CameraParams camera;
        ls::LightParams light;
        double mostArea;  // the rectangle's largest fraction of the screen (1: may be whole)
    };
    ls::LightParams point;
    point.kind = ls::LightType::Point;
    point.position = {2.0f, 1.0f, -8.0f};
    point.range = 1.5f;
    ls::LightParams pointNear = point;
    pointNear.position = {0.0f, 0.0f, 0.5f};  // the camera inside its range
    const Case cases[] = {
        {"small spot ahead", camera({0, 1, 6}, {0, 1, 0}, screen),
         spot({-2, 4, -4}, {0.1f, -1, 0}, 12.0f, 6.0f), 0.15},
        {"spot seen from the side", camera({0, 1, 6}, {0, 1, 0}, screen),
         spot({3, 1, -2}, {-1, -0.2f, 0.1f}, 20.0f, 8.0f), 0.5},
        {"wide spot over the camera", camera({0, 1, 6}, {0, 1, 0}, screen),
         spot({0, 5, 6}, {0, -1, 0}, 50.0f, 20.0f), 1.0},
        {"spot behind the camera, pointing past it", camera({0, 1, 6}, {0, 1, 0}, screen),
         spot({0, 2, 12}, {0, -0.3f, -1}, 15.0f, 30.0f), 1.0},
        {"small point light", camera({0, 1, 6}, {0, 1, 0}, screen), point, 0.1},
        {"point light around the camera", camera({0, 0, 0}, {0, 0, -1}, screen), pointNear, 1.0},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        const VkRect2D rect = ls::lightScreenRect(c.camera, c.light, medium, screen);
        const Coverage k = coverage(c.camera, c.light, screen, rect);
        const double area = static_cast<double>(rect.extent.width) * rect.extent.height /
                            (static_cast<double>(screen.width) * screen.height);
        std::printf(
            "%s: %d pixels reached, %d outside the rectangle; the rectangle %.1f%% of the "
            "screen\n",
            c.what, k.reached, k.outside, 100.0 * area);
        EXPECT_GT(k.reached, 0);
        EXPECT_EQ(k.outside, 0);
        EXPECT_LE(area, c.mostArea);
    }
}

// A directional light, or a point light without a range, reaches every pixel.
TEST(LightScreenRect, AnUnboundedLightIsTheWholeScreen) {
    const VkExtent2D screen{96, 54};
    ls::LightParams sun;
    ls::LightParams point;
    point.kind = ls::LightType::Point;
    point.position = {0.0f, 1.0f, -3.0f};
    for (const ls::LightParams& l : {sun, point}) {
        const VkRect2D r = ls::lightScreenRect(camera({0, 1, 6}, {0, 1, 0}, screen), l, {}, screen);
        EXPECT_EQ(r.offset.x, 0);
        EXPECT_EQ(r.offset.y, 0);
        EXPECT_EQ(r.extent.width, screen.width);
        EXPECT_EQ(r.extent.height, screen.height);
    }
}

}  // namespace
