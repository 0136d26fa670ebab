#pragma once
// Small scenes for plugin tests: parallelograms ray-cast in double precision into the camera's
// depth buffer and the light's shadow map at pixel and texel centres, as a rasterizer would sample
// them.
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <vector>

#include <lightscatter/lightscatter.h>

namespace plugin_test {

struct Quad {
    glm::dvec3 center, u, v;  // the points center + a u + b v, |a|, |b| <= 1
};

struct Scene {
    std::vector<Quad> quads;
    double intersect(const glm::dvec3& o, const glm::dvec3& d) const;  // t, or +inf
};

struct View {
    glm::mat4 view{1.0f}, projection{1.0f};
    float nearPlane = 0.1f, farPlane = 100.0f;
    bool reversedZ = false, infiniteFar = false;
    glm::dmat4 viewProj() const { return glm::dmat4(projection) * glm::dmat4(view); }
    lightscatter::Camera camera() const;
};

// The depth-buffer values a rasterizer would store (sky: the far value).
std::vector<float> renderDepth(const Scene& scene, const View& view, uint32_t width,
                               uint32_t height);

// Shadow map of a light whose world -> clip matrix is `lightViewProj` (standard depth, 1 = empty).
// Empty texels hold the far value: 1, or 0 for a reversed-z projection.
std::vector<float> renderShadowMap(const Scene& scene, const glm::mat4& lightViewProj,
                                   uint32_t size, bool reversedZ = false);

// The ray through a pixel centre and the distance S to its end (surface, or the sky rule of
// docs/model.md), in double.
struct PixelRay {
    glm::dvec3 origin, dir;
    double S;
};
PixelRay pixelRay(const Scene& scene, const View& view, uint32_t width, uint32_t height, uint32_t x,
                  uint32_t y, double maxDistance);

lightscatter::Mat4 toMat4(const glm::mat4& m);

// Scenes used by several tests.
Scene grilleScene();  // ground, a grille of bars above it, a box
View lookAt(glm::vec3 eye, glm::vec3 target, float fovDegrees, float aspect, float nearP,
            float farP, bool reversedZ = false, bool infiniteFar = false);
glm::mat4 spotShadowMatrix(const lightscatter::Light& light, float nearP, float farP);
glm::mat4 directionalShadowMatrix(const glm::vec3& direction, const glm::vec3& center,
                                  float radius);

}  // namespace plugin_test
