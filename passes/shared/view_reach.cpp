#include "view_reach.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

namespace ls {
namespace {

// How far from a point or spot light a point can lie and still be on a view ray: its range, and
// the view's reach (view rays end within the far plane's corners, or the sky distance with an
// infinite far plane) beyond the light's distance from the camera.
float reachFromLight(const CameraParams& camera, const LightParams& light,
                     const MediumParams& medium) {
    const glm::vec3 cameraPos = glm::vec3(glm::inverse(camera.view)[3]);
    const float tanX = 1.0f / std::fabs(camera.projection[0][0]);
    const float tanY = 1.0f / std::fabs(camera.projection[1][1]);
    const float farthest = (camera.infiniteFar ? medium.maxDistance : camera.farPlane) *
                           std::sqrt(1.0f + tanX * tanX + tanY * tanY);
    return std::min(light.range, glm::length(light.position - cameraPos) + farthest);
}

}  // namespace

bool lightTouchesView(const CameraParams& camera, const LightParams& light,
                      const MediumParams& medium) {
    // Nothing reaches the camera when nothing is emitted or nothing scatters.
    if (glm::all(glm::equal(light.intensity, glm::vec3(0.0f)))) return false;
    if (glm::all(glm::equal(medium.betaR + medium.betaM, glm::vec3(0.0f)))) return false;
    if (light.kind != LightType::Spot) return true;
    // View rays end within the far plane's corners (or the sky distance with an infinite far
    // plane), so only the part of the cone within that reach of the camera can matter: an
    // unbounded spot is bounded by it.
    const float range = reachFromLight(camera, light, medium);
    if (!(range < 1e29f)) return true;
    const glm::mat4 m = glm::transpose(camera.projection * camera.view);  // rows as columns
    glm::vec4 planes[6] = {m[3] + m[0], m[3] - m[0], m[3] + m[1], m[3] - m[1], m[2], m[3] - m[2]};
    const int count = camera.infiniteFar ? 5 : 6;
    const glm::vec3 axis = glm::normalize(light.direction);
    const float alpha = std::acos(std::clamp(light.cosOuter, -1.0f, 1.0f));
    for (int i = 0; i < count; ++i) {
        const glm::vec3 n(planes[i]);
        const float len = glm::length(n);
        if (len < 1e-12f) continue;
        // The farthest reach of the range-capped cone along the plane's normal.
        const float angle = std::acos(std::clamp(glm::dot(n / len, axis), -1.0f, 1.0f));
        const float reach =
            angle <= alpha ? 1.0f : std::max(0.0f, std::cos(std::min(angle - alpha, 1.5707964f)));
        if ((glm::dot(n, light.position) + planes[i].w) / len + range * reach < 0.0f) return false;
    }
    return true;
}

bool cubeFaceTouchesView(const CameraParams& camera, const LightParams& light,
                         const MediumParams& medium, int face) {
    if (!lightTouchesView(camera, light, medium)) return false;
    // Two convex solids, each given by its corners: the view (its frustum up to the depth no view
    // ray passes: the far plane, or the sky distance with an infinite far plane) and the face's
    // pyramid from the light (up to the farthest the view reaches from the light). They miss each
    // other when one's corners all lie outside one plane of the other (conservative: some that
    // miss are kept).
    const glm::mat4 invView = glm::inverse(camera.view);
    const glm::vec3 cameraPos(invView[3]);
    const glm::vec3 forward = -glm::normalize(glm::vec3(invView[2]));
    const float depth = camera.infiniteFar ? medium.maxDistance : camera.farPlane;
    const glm::mat4 invViewProj = glm::inverse(camera.projection * camera.view);
    const float nearNdc = camera.reversedZ ? 1.0f : 0.0f;
    glm::vec3 view[8];
    float reach = 0.0f;
    for (int k = 0; k < 4; ++k) {
        const glm::vec4 c =
            invViewProj * glm::vec4(k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, nearNdc, 1.0f);
        const glm::vec3 d = glm::vec3(c) / c.w - cameraPos;
        const float along = glm::dot(d, forward);
        if (!(along > 0.0f)) return true;  // not a perspective view this test understands
        view[k] = cameraPos + d * (camera.nearPlane / along);
        view[k + 4] = cameraPos + d * (depth / along);
        reach = std::max(reach, glm::length(view[k + 4] - cameraPos));
    }
    // The face's side planes through the light: s D[axis] >= |D[other]| with D = P - light.
    const int axis = face / 2;
    const float sign = face % 2 == 0 ? 1.0f : -1.0f;
    for (int k = 1; k <= 2; ++k) {
        const int other = (axis + k) % 3;
        for (float side : {-1.0f, 1.0f}) {
            bool allOutside = true;
            for (const glm::vec3& p : view) {
                const glm::vec3 d = p - light.position;
                allOutside = allOutside && sign * d[axis] + side * d[other] < 0.0f;
            }
            if (allOutside) return false;
        }
    }
    // The pyramid's corners against the view's planes.
    const float range = glm::length(light.position - cameraPos) + reach;
    glm::vec3 pyramid[5] = {light.position};
    for (int k = 0; k < 4; ++k) {
        glm::vec3 d(0.0f);
        d[axis] = sign * range;
        d[(axis + 1) % 3] = k & 1 ? range : -range;
        d[(axis + 2) % 3] = k & 2 ? range : -range;
        pyramid[k + 1] = light.position + d;
    }
    const glm::mat4 m = glm::transpose(camera.projection * camera.view);  // rows as columns
    const glm::vec4 planes[6] = {m[3] + m[0], m[3] - m[0], m[3] + m[1],
                                 m[3] - m[1], m[2],        m[3] - m[2]};
    for (int i = 0; i < (camera.infiniteFar ? 5 : 6); ++i) {
        bool allOutside = true;
        for (const glm::vec3& p : pyramid)
            allOutside = allOutside && glm::dot(glm::vec4(p, 1.0f), planes[i]) < 0.0f;
        if (allOutside) return false;
    }
    return true;
}

std::optional<std::vector<glm::vec2>> lightScreenCorners(const CameraParams& camera,
                                                         const LightParams& light,
                                                         const MediumParams& medium,
                                                         bool clipToNear) {
    if (light.kind == LightType::Directional) return std::nullopt;
    // How far from the light a point can lie and still be on a view ray: its range, and the
    // view's reach (as lightTouchesView bounds it) beyond the light's distance from the camera.
    const float extent = reachFromLight(camera, light, medium);
    if (!(extent < 1e6f)) return std::nullopt;
    // Corners of a convex solid holding the volume: a point light's cube around its sphere; for
    // a spot, its apex and an octagon around the cone's circle at `extent` along the axis (every
    // point of the cone within `extent` of the apex lies inside that truncated pyramid).
    std::vector<glm::vec3> corners;
    if (light.kind == LightType::Point) {
        for (int k = 0; k < 8; ++k)
            corners.push_back(light.position +
                              extent * glm::vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
    } else {
        const glm::vec3 axis = glm::normalize(light.direction);
        const float cosA = std::clamp(light.cosOuter, 1e-6f, 1.0f);
        const float radius = extent * std::sqrt(std::max(0.0f, 1.0f - cosA * cosA)) / cosA /
                             std::cos(3.14159265f / 8.0f);
        if (!(radius < 1e6f)) return std::nullopt;
        const glm::vec3 helper =
            std::fabs(axis.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
        const glm::vec3 u = glm::normalize(glm::cross(axis, helper));
        const glm::vec3 w = glm::cross(axis, u);
        corners.push_back(light.position);
        for (int k = 0; k < 8; ++k) {
            const float a = 3.14159265f / 4.0f * static_cast<float>(k);
            corners.push_back(light.position + extent * axis +
                              radius * (std::cos(a) * u + std::sin(a) * w));
        }
    }
    // Projected, the solid's corners bound its pixels, if all lie in front of the camera's near
    // plane (a corner behind it: the solid wraps around the camera, or beside it; unsure).
    const glm::mat4 viewProj = camera.projection * camera.view;
    const float nearW = 0.5f * camera.nearPlane;
    std::vector<glm::vec4> clip;
    for (const glm::vec3& p : corners) clip.push_back(viewProj * glm::vec4(p, 1.0f));
    std::vector<glm::vec2> ndc;
    for (const glm::vec4& c : clip) {
        if (c.w > nearW) {
            ndc.emplace_back(c.x / c.w, c.y / c.w);
        } else if (!clipToNear || light.kind != LightType::Spot || &c == &clip[0]) {
            return std::nullopt;
        }
    }
    if (ndc.size() == clip.size()) return ndc;
    // A spot's pyramid cut by that plane (no view ray passes behind it): where its edges, from
    // the apex and around the octagon, cross it.
    auto cut = [&](const glm::vec4& a, const glm::vec4& b) {
        if ((a.w > nearW) == (b.w > nearW)) return;
        const glm::vec4 p = a + (a.w - nearW) / (a.w - b.w) * (b - a);
        ndc.emplace_back(p.x / nearW, p.y / nearW);
    };
    for (size_t k = 1; k < clip.size(); ++k) {
        cut(clip[0], clip[k]);
        cut(clip[k], clip[k % (clip.size() - 1) + 1]);
    }
    return ndc;
}

VkRect2D lightScreenRect(const CameraParams& camera, const LightParams& light,
                         const MediumParams& medium, VkExtent2D screen) {
    const VkRect2D whole{{0, 0}, screen};
    const auto corners = lightScreenCorners(camera, light, medium, false);
    if (!corners) return whole;
    float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
    for (const glm::vec2& p : *corners) {
        const float x = (p.x * 0.5f + 0.5f) * static_cast<float>(screen.width);
        const float y = (p.y * 0.5f + 0.5f) * static_cast<float>(screen.height);
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
    }
    // A pixel on the border, and float rounding: one more pixel each side.
    auto clampTo = [](float v, uint32_t size) {
        return static_cast<int32_t>(std::clamp(v, 0.0f, static_cast<float>(size)));
    };
    const int32_t left = clampTo(std::floor(x0) - 1.0f, screen.width);
    const int32_t right = clampTo(std::ceil(x1) + 1.0f, screen.width);
    const int32_t top = clampTo(std::floor(y0) - 1.0f, screen.height);
    const int32_t bottom = clampTo(std::ceil(y1) + 1.0f, screen.height);
    return {{left, top},
            {static_cast<uint32_t>(std::max(0, right - left)),
             static_cast<uint32_t>(std::max(0, bottom - top))}};
}

}  // namespace ls
