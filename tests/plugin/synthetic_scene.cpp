#include "synthetic_scene.h"

#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "support/projection.h"

namespace plugin_test {

double Scene::intersect(const glm::dvec3& o, const glm::dvec3& d) const {
    double best = std::numeric_limits<double>::infinity();
    for (const Quad& q : quads) {
        const glm::dvec3 n = glm::cross(q.u, q.v);
        const double denom = glm::dot(d, n);
        if (std::fabs(denom) < 1e-14) continue;
        const double t = glm::dot(q.center - o, n) / denom;
        if (!(t > 1e-9) || t >= best) continue;
        const glm::dvec3 p = o + t * d - q.center;
        if (std::fabs(glm::dot(p, q.u)) <= glm::dot(q.u, q.u) &&
            std::fabs(glm::dot(p, q.v)) <= glm::dot(q.v, q.v))
            best = t;
    }
    return best;
}

lightscatter::Camera View::camera() const {
    lightscatter::Camera c;
    c.view = toMat4(view);
    c.projection = toMat4(projection);
    c.nearPlane = nearPlane;
    c.farPlane = farPlane;
    c.reversedZ = reversedZ;
    c.infiniteFar = infiniteFar;
    return c;
}

lightscatter::Mat4 toMat4(const glm::mat4& m) {
    lightscatter::Mat4 out;
    std::memcpy(out.data(), &m[0][0], sizeof(float) * 16);
    return out;
}

namespace {

// Ray through NDC (x, y) of a projection, in world space.
void unprojectRay(const glm::dmat4& inv, double x, double y, glm::dvec3& o, glm::dvec3& d) {
    glm::dvec4 a = inv * glm::dvec4(x, y, 0.0, 1.0);
    glm::dvec4 b = inv * glm::dvec4(x, y, 0.5, 1.0);
    a /= a.w;
    b /= b.w;
    o = glm::dvec3(a);
    d = glm::normalize(glm::dvec3(b) - glm::dvec3(a));
}

}  // namespace

PixelRay pixelRay(const Scene& scene, const View& view, uint32_t width, uint32_t height, uint32_t x,
                  uint32_t y, double maxDistance) {
    const double nx = (x + 0.5) / width * 2.0 - 1.0, ny = (y + 0.5) / height * 2.0 - 1.0;
    PixelRay r;
    r.origin = glm::dvec3(glm::inverse(glm::dmat4(view.view))[3]);
    // The view-space direction whose clip x and y are nx and ny times its clip w: orthogonal to
    // rows 0 - nx row 3 and 1 - ny row 3 of the projection. Unprojecting a point and subtracting
    // the camera's position would cancel, even in double, with a near plane of 1e-15 m.
    const glm::dmat4 p(view.projection);
    auto row = [&](int i) { return glm::dvec3(p[0][i], p[1][i], p[2][i]); };
    glm::dvec3 d = glm::cross(row(0) - nx * row(3), row(1) - ny * row(3));
    if (glm::dot(d, row(3)) < 0.0) d = -d;  // ahead: clip w > 0
    r.dir = glm::normalize(glm::inverse(glm::dmat3(glm::dmat4(view.view))) * d);
    const glm::dvec3 forward = -glm::normalize(glm::dvec3(glm::inverse(glm::dmat4(view.view))[2]));
    const double cosAxis = glm::dot(r.dir, forward);
    double t = scene.intersect(r.origin, r.dir);
    // Beyond the far plane a surface is clipped: that pixel is sky.
    if (!view.infiniteFar && t * cosAxis > view.farPlane)
        t = std::numeric_limits<double>::infinity();
    if (std::isinf(t)) {
        t = maxDistance;
        if (!view.infiniteFar) t = std::min(view.farPlane / cosAxis, maxDistance);
    }
    r.S = t;
    return r;
}

std::vector<float> renderDepth(const Scene& scene, const View& view, uint32_t width,
                               uint32_t height) {
    std::vector<float> depth(size_t{width} * height);
    const glm::dmat4 vp = view.viewProj();
    const glm::dvec3 eye = glm::dvec3(glm::inverse(glm::dmat4(view.view))[3]);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const PixelRay r = pixelRay(scene, view, width, height, x, y, 1e30);
            const double t = scene.intersect(eye, r.dir);
            float value = view.reversedZ ? 0.0f : 1.0f;
            if (std::isfinite(t)) {
                const glm::dvec4 clip = vp * glm::dvec4(eye + t * r.dir, 1.0);
                const double z = clip.z / clip.w;
                if (z >= 0.0 && z <= 1.0) value = static_cast<float>(z);
            }
            depth[size_t{y} * width + x] = value;
        }
    return depth;
}

std::vector<float> renderShadowMap(const Scene& scene, const glm::mat4& lightViewProj,
                                   uint32_t size, bool reversedZ) {
    std::vector<float> depth(size_t{size} * size, reversedZ ? 0.0f : 1.0f);
    const glm::dmat4 m(lightViewProj);
    const glm::dmat4 inv = glm::inverse(m);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const double nx = (x + 0.5) / size * 2.0 - 1.0, ny = (y + 0.5) / size * 2.0 - 1.0;
            glm::dvec3 o, d;
            unprojectRay(inv, nx, ny, o, d);
            const double t = scene.intersect(o, d);
            if (!std::isfinite(t)) continue;
            const glm::dvec4 clip = m * glm::dvec4(o + t * d, 1.0);
            const double z = clip.z / clip.w;
            if (z >= 0.0 && z <= 1.0) depth[size_t{y} * size + x] = static_cast<float>(z);
        }
    return depth;
}

Scene grilleScene() {
    Scene s;
    s.quads.push_back({{0, 0, 0}, {20, 0, 0}, {0, 0, -20}});  // ground, facing up
    for (int i = -2; i <= 2; ++i)                             // bars of a grille at y = 3
        s.quads.push_back({{0.5 * i, 3.0, 0}, {0.12, 0, 0}, {0, 0, -1.6}});
    s.quads.push_back({{-1.2, 1.0, 0.4}, {0.5, 0, 0}, {0, 1.0, 0}});  // a wall piece
    return s;
}

View lookAt(glm::vec3 eye, glm::vec3 target, float fovDegrees, float aspect, float nearP,
            float farP, bool reversedZ, bool infiniteFar) {
    View v;
    glm::vec3 up(0, 1, 0);
    if (std::fabs(glm::dot(glm::normalize(target - eye), up)) > 0.999f) up = glm::vec3(0, 0, -1);
    v.view = glm::lookAtRH(eye, target, up);
    v.projection = testing_support::vulkanPerspective(glm::radians(fovDegrees), aspect, nearP, farP,
                                                      reversedZ, infiniteFar);
    v.nearPlane = nearP;
    v.farPlane = farP;
    v.reversedZ = reversedZ;
    v.infiniteFar = infiniteFar;
    return v;
}

glm::mat4 spotShadowMatrix(const lightscatter::Light& light, float nearP, float farP) {
    const glm::vec3 pos(light.position[0], light.position[1], light.position[2]);
    const glm::vec3 dir =
        glm::normalize(glm::vec3(light.direction[0], light.direction[1], light.direction[2]));
    glm::vec3 up(0, 1, 0);
    if (std::fabs(glm::dot(dir, up)) > 0.999f) up = glm::vec3(0, 0, -1);
    const glm::mat4 view = glm::lookAtRH(pos, pos + dir, up);
    // A little wider than the cone, so the cone's edge falls inside the map.
    const float fov = 2.0f * glm::radians(std::min(light.outerConeAngleDegrees + 2.0f, 89.0f));
    return testing_support::vulkanPerspective(fov, 1.0f, nearP, farP, light.shadowReversedZ,
                                              false) *
           view;
}

glm::mat4 directionalShadowMatrix(const glm::vec3& direction, const glm::vec3& center,
                                  float radius) {
    const glm::vec3 dir = glm::normalize(direction);
    glm::vec3 up(0, 1, 0);
    if (std::fabs(glm::dot(dir, up)) > 0.999f) up = glm::vec3(0, 0, -1);
    const glm::mat4 view = glm::lookAtRH(center - dir * (2.0f * radius), center, up);
    return testing_support::vulkanOrtho(radius, radius, radius, 3.0f * radius) * view;
}

}  // namespace plugin_test
