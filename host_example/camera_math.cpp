#include "camera_math.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace host {
namespace {

glm::vec3 safeUp(const glm::vec3& forward, const glm::vec3& up) {
    if (std::fabs(glm::dot(glm::normalize(forward), glm::normalize(up))) > 0.999f)
        return std::fabs(forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, -1);
    return up;
}

}  // namespace

glm::mat4 vulkanPerspective(float fovY, float aspect, float nearP, float farP, bool reversed,
                            bool infinite) {
    glm::mat4 p(0.0f);
    const float f = 1.0f / std::tan(fovY * 0.5f);
    p[0][0] = f / aspect;
    p[1][1] = -f;
    p[2][3] = -1.0f;
    if (infinite) {
        p[2][2] = reversed ? 0.0f : -1.0f;
        p[3][2] = reversed ? nearP : -nearP;
    } else if (reversed) {
        p[2][2] = nearP / (farP - nearP);
        p[3][2] = farP * nearP / (farP - nearP);
    } else {
        p[2][2] = farP / (nearP - farP);
        p[3][2] = farP * nearP / (nearP - farP);
    }
    return p;
}

glm::mat4 vulkanOrtho(float halfWidth, float halfHeight, float nearP, float farP) {
    glm::mat4 p = glm::orthoRH_ZO(-halfWidth, halfWidth, -halfHeight, halfHeight, nearP, farP);
    p[1][1] = -p[1][1];
    return p;
}

glm::mat4 cameraView(const CameraDesc& c) {
    return glm::lookAtRH(c.position, c.target, safeUp(c.target - c.position, c.up));
}

glm::mat4 cameraProjection(const CameraDesc& c, float aspect) {
    return vulkanPerspective(glm::radians(c.fovYDegrees), aspect, c.nearPlane, c.farPlane, c.reversedZ,
                             c.infiniteFar);
}

glm::mat4 shadowViewProjection(const LightDesc& light, const Bounds& scene) {
    const glm::vec3 dir = glm::normalize(light.direction);
    const glm::vec3 center = scene.empty() ? glm::vec3(0.0f) : (scene.min + scene.max) * 0.5f;
    const float radius = scene.empty() ? 1.0f : std::max(glm::length(scene.max - scene.min) * 0.5f, 1e-3f);
    if (light.type == LightKind::Spot) {
        const glm::mat4 view = glm::lookAtRH(light.position, light.position + dir, safeUp(dir, {0, 1, 0}));
        const float farthest = glm::length(center - light.position) + radius;
        const float farP = std::max(std::min(light.range, farthest), 0.1f);
        const float nearP = std::clamp(farP * 1e-3f, 1e-3f, 0.05f);
        // A little wider than the cone so its edge lies inside the map.
        const float fov = 2.0f * glm::radians(std::min(light.halfAngleDegrees + 2.0f, 89.5f));
        return vulkanPerspective(fov, 1.0f, nearP, farP, false, false) * view;
    }
    const glm::mat4 view = glm::lookAtRH(center - dir * (2.0f * radius), center, safeUp(dir, {0, 1, 0}));
    return vulkanOrtho(radius, radius, radius, 3.0f * radius) * view;
}

}  // namespace host
