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
    return vulkanPerspective(glm::radians(c.fovYDegrees), aspect, c.nearPlane, c.farPlane,
                             c.reversedZ, c.infiniteFar);
}

namespace {

glm::vec3 corner(const Bounds& b, int i) {
    return {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
}

// An orthographic light-space box: x and y across the light, depths along it. Usable when every
// extent is finite and wider than a float's resolution at its coordinates; a box that is not (a
// scene of one point, a part seen edge on) would give the map a division by zero.
struct LightBox {
    glm::vec2 lo, hi;
    float nearP = 0.0f, farP = 0.0f;
};

bool resolvable(float a, float b) {
    const float magnitude = std::max(std::fabs(a), std::fabs(b));
    return std::isfinite(a) && std::isfinite(b) && b - a > 16.0f * magnitude * 1.2e-7f;
}

bool usable(const LightBox& b) {
    return resolvable(b.lo.x, b.hi.x) && resolvable(b.lo.y, b.hi.y) && resolvable(b.nearP, b.farP);
}

// The margins that keep edge texels off the border and every caster inside the depth range: a
// percent of the extent, a millimetre, and at least a millionth of the world's coordinates
// (`world`: how far from the origin the scene reaches), some sixteen times what float32 rounds
// them by, so that an extent of nothing becomes one the map resolves. A scene within a kilometre
// of the origin keeps the millimetre.
LightBox padded(glm::vec2 lo, glm::vec2 hi, float nearest, float farthest, float radius,
                float world) {
    const float across = std::max(1e-3f, 1e-6f * world);
    const glm::vec2 pad = (hi - lo) * 0.01f + glm::vec2(across);
    const float along = std::max(1e-3f * radius, 1e-6f * world);
    return {lo - pad, hi + pad, std::max(nearest - along, 1e-4f), farthest + along};
}

glm::mat4 orthoFor(const LightBox& b, const glm::mat4& view) {
    glm::mat4 p = glm::orthoRH_ZO(b.lo.x, b.hi.x, b.lo.y, b.hi.y, b.nearP, b.farP);
    p[1][1] = -p[1][1];  // Vulkan clip: y down
    p[3][1] = -p[3][1];
    return p * view;
}

bool finiteMatrix(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// Whether a box may be seen: not all of its corners beyond one side of the view frustum.
bool mayBeSeen(const Bounds& b, const glm::mat4& view, float tanX, float tanY, float nearD,
               float farD) {
    bool out[6] = {true, true, true, true, true, true};
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 v = glm::vec3(view * glm::vec4(corner(b, i), 1.0f));
        const float d = -v.z;
        out[0] = out[0] && d < nearD;
        out[1] = out[1] && d > farD;
        out[2] = out[2] && v.x < -tanX * d;
        out[3] = out[3] && v.x > tanX * d;
        out[4] = out[4] && v.y < -tanY * d;
        out[5] = out[5] && v.y > tanY * d;
    }
    for (bool o : out)
        if (o) return false;
    return true;
}

}  // namespace

glm::mat4 shadowViewProjection(const LightDesc& light, const Bounds& scene,
                               const std::vector<Bounds>& parts, const CameraDesc& camera,
                               float aspect) {
    const glm::vec3 dir = glm::normalize(light.direction);
    const glm::vec3 center = scene.empty() ? glm::vec3(0.0f) : (scene.min + scene.max) * 0.5f;
    // At least a millimetre, and a hundred thousandth of the distance from the origin: the light's
    // eye stands two radii from the centre, which float32 must tell apart from it.
    const float radius = scene.empty() ? 1.0f
                                       : std::max({glm::length(scene.max - scene.min) * 0.5f, 1e-3f,
                                                   1e-5f * glm::length(center)});
    if (light.type == lightscatter::LightType::Spot) {
        const glm::mat4 view =
            glm::lookAtRH(light.position, light.position + dir, safeUp(dir, {0, 1, 0}));
        const float farthest = glm::length(center - light.position) + radius;
        const float farP = std::max(std::min(light.range, farthest), 0.1f);
        const float nearP = std::clamp(farP * 1e-3f, 1e-3f, 0.05f);
        // A little wider than the cone so its edge lies inside the map.
        const float fov = 2.0f * glm::radians(std::min(light.outerConeAngleDegrees + 2.0f, 89.5f));
        return vulkanPerspective(fov, 1.0f, nearP, farP, false, false) * view;
    }
    const glm::mat4 view =
        glm::lookAtRH(center - dir * (2.0f * radius), center, safeUp(dir, {0, 1, 0}));
    if (scene.empty()) return vulkanOrtho(radius, radius, radius, 3.0f * radius) * view;

    // Depth covers the whole scene, so that every caster between the sun and the view is in the
    // map.
    glm::vec3 sceneMin(1e30f), sceneMax(-1e30f);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 l = glm::vec3(view * glm::vec4(corner(scene, i), 1.0f));
        sceneMin = glm::min(sceneMin, l);
        sceneMax = glm::max(sceneMax, l);
    }
    // Across the light, only what the camera can see needs texels (the usual fitting of cascaded
    // shadow maps, with one cascade): the parts of the scene inside the view frustum, each clipped
    // to the frustum's extent, the frustum cut at the farthest of them. Outside the parts nothing
    // casts a shadow, so texels there are wasted.
    const glm::mat4 cameraV = cameraView(camera);
    const glm::mat4 invView = glm::inverse(cameraV);
    const float tanY = std::tan(glm::radians(camera.fovYDegrees) * 0.5f), tanX = tanY * aspect;
    const float nearD = camera.nearPlane;
    const float farLimit = camera.infiniteFar ? 1e30f : camera.farPlane;
    const std::vector<Bounds> whole{scene};
    const std::vector<Bounds>& boxes = parts.empty() ? whole : parts;
    std::vector<const Bounds*> seen;
    float farD = nearD;
    for (const Bounds& b : boxes) {
        if (b.empty() || !mayBeSeen(b, cameraV, tanX, tanY, nearD, farLimit)) continue;
        seen.push_back(&b);
        for (int i = 0; i < 8; ++i)
            farD = std::max(farD, glm::length(corner(b, i) - camera.position));
    }
    farD = std::min(farD, farLimit);
    glm::vec2 viewMin(1e30f), viewMax(-1e30f);
    for (int i = 0; i < 8; ++i) {
        const float d = (i & 4) ? farD : nearD;
        const glm::vec4 p(((i & 1) ? 1.0f : -1.0f) * tanX * d, ((i & 2) ? 1.0f : -1.0f) * tanY * d,
                          -d, 1.0f);
        const glm::vec2 l = glm::vec2(view * (invView * p));
        viewMin = glm::min(viewMin, l);
        viewMax = glm::max(viewMax, l);
    }
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (const Bounds* b : seen) {
        glm::vec2 partMin(1e30f), partMax(-1e30f);
        for (int i = 0; i < 8; ++i) {
            const glm::vec2 l = glm::vec2(view * glm::vec4(corner(*b, i), 1.0f));
            partMin = glm::min(partMin, l);
            partMax = glm::max(partMax, l);
        }
        partMin = glm::max(partMin, viewMin);
        partMax = glm::min(partMax, viewMax);
        // A part of no width (one seen edge on, or a single point) is still in view.
        if (partMin.x > partMax.x || partMin.y > partMax.y) continue;
        lo = glm::min(lo, partMin);
        hi = glm::max(hi, partMax);
    }
    // The scene's own box when the view shows nothing of it, or when what it shows makes no box
    // a float can hold (the view-fitted box must never be the one that fails: issue #22).
    const float world = glm::length(center) + 3.0f * radius;
    const LightBox sceneBox =
        padded(glm::vec2(sceneMin), glm::vec2(sceneMax), -sceneMax.z, -sceneMin.z, radius, world);
    const LightBox fitted = lo.x <= hi.x && lo.y <= hi.y
                                ? padded(lo, hi, -sceneMax.z, -sceneMin.z, radius, world)
                                : sceneBox;
    if (usable(fitted)) {
        const glm::mat4 m = orthoFor(fitted, view);
        if (finiteMatrix(m)) return m;
    }
    return orthoFor(sceneBox, view);
}

std::array<glm::mat4, 6> cubeFaceViewProjections(const LightDesc& light, const Bounds& scene) {
    float farthest = 1.0f;
    if (!scene.empty())
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 corner((c & 1) ? scene.max.x : scene.min.x,
                                   (c & 2) ? scene.max.y : scene.min.y,
                                   (c & 4) ? scene.max.z : scene.min.z);
            farthest = std::max(farthest, glm::length(corner - light.position));
        }
    const float nearP = 0.02f, farP = 1.05f * farthest + 1.0f;
    const glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(90.0f), 1.0f, nearP, farP);
    static const glm::vec3 kAxes[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    static const glm::vec3 kUps[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                                      {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    std::array<glm::mat4, 6> faces;
    for (size_t i = 0; i < 6; ++i)
        faces[i] = projection * glm::lookAtRH(light.position, light.position + kAxes[i], kUps[i]);
    return faces;
}

}  // namespace host
