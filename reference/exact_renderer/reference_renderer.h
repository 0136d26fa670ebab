#pragma once
// The exact CPU reference of issue #5: Lin of docs/model.md for every pixel centre of a scene, in
// float64, with exact visibility traced against the scene's triangles (a BVH, not a shadow map).
// Every GPU method is judged against this image.
//
// A scene of several lights ("lights") gets the sum of each light's Lin, each light with its own
// exact visibility: a frame of several lights is judged as the plugin composites it.
//
// Point lights: docs/model.md's V is exact visibility, so this reference shadows them by default,
// whether or not the GPU is given a cube shadow map. A comparison of an unshadowed GPU point light
// against it therefore counts the missing shadows as error, which is the model's intended judging;
// pass `shadows = false` for the unshadowed image instead.
//
// A spot's cookie (SceneDesc's light.cookie) multiplies its irradiance as docs/model.md says: the
// image's linear value (sRGB decoded, then bilinear, clamped to the edge texels, as the GPU samples
// the host's R8G8B8A8_SRGB image) where the host's shadowViewProjection projects the point, 1
// outside the image or behind the light.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "bvh.h"
#include "camera_rays.h"
#include "float64_model/interval.h"
#include "float64_model/light.h"
#include "float64_model/medium.h"
#include "float64_model/ray.h"
#include "scene/scene.h"

namespace host::reference {

struct ReferenceOptions {
    uint32_t threads = 0;          // 0: std::thread::hardware_concurrency()
    double relTol = 1e-6;          // quadrature tolerance per channel (point and spot lights)
    int visibilitySamples = 512;   // visibility samples per view ray, uniform over [0, S]
    double boundaryRelTol = 1e-9;  // shadow boundaries are bisected to this fraction of S
    bool shadows = true;           // false: V = 1 inside the light's volume
    // Shadow rays through Embree's traversal (where the build has it) or the double BVH's own:
    // the same image bit for bit either way, Embree's about 3x sooner.
    Bvh::Traversal traversal = Bvh::Traversal::Embree;
};

struct ReferenceImage {
    uint32_t width = 0, height = 0;
    std::vector<double> rgb;       // Lin, 3 per pixel, row-major, row 0 at the top
    std::vector<double> distance;  // S per pixel (the sky's S for sky pixels)
};

// SceneDesc's light and medium as the float64 model takes them: the direction normalised, the
// spot's half-angle in radians, r0 = radius. A spot's range is kept as given (the scene's default
// 1e30 m is effectively infinite); a point light has none. A homogeneous medium's density is folded
// into its coefficients as the plugin folds it (in float), so that its model is the homogeneous
// one; a non-uniform medium keeps its coefficients and takes density, height fog and volumes (axes
// normalised in double) as its ls::ref::Density.
[[nodiscard]] ls::ref::Light toReferenceLight(const LightDesc& light);
[[nodiscard]] ls::ref::Medium toReferenceMedium(const MediumDesc& medium);

// One scene prepared for a screen size: BVH, camera, lights and medium. For callers (and tests)
// that need single rays; renderReference runs it over every pixel.
class ReferenceScene {
  public:
    ReferenceScene(const SceneDesc& scene, const MeshData& mesh, uint32_t width, uint32_t height,
                   const ReferenceOptions& options = {});

    // Pixel (x, y)'s view ray: from the eye through the pixel's centre, unit direction, length S.
    [[nodiscard]] ls::ref::Ray pixelRay(uint32_t x, uint32_t y) const;
    // The view ray along any unit direction from the eye, ending as a pixel's would.
    [[nodiscard]] ls::ref::Ray viewRay(const glm::dvec3& direction) const;
    // The lit intervals of a ray with a unit direction for lights()[light] (see litIntervals in
    // visibility.h).
    [[nodiscard]] std::vector<ls::ref::Interval> litIntervals(const ls::ref::Ray& ray,
                                                              std::size_t light = 0) const;
    // Lin of lights()[light] along a ray with a unit direction: the directional closed form over
    // the lit intervals (exact), or ls::ref::integrateInscatter to relTol for point and spot
    // lights.
    [[nodiscard]] glm::dvec3 inscatter(const ls::ref::Ray& ray, std::size_t light) const;
    // Lin of every light along the ray: the sum of the above, in the scene's order of lights.
    [[nodiscard]] glm::dvec3 inscatter(const ls::ref::Ray& ray) const;
    // T(S) of the ray per channel, exp(-betaT tau(S)): the composite is Lobj T(S) + Lin.
    [[nodiscard]] glm::dvec3 transmittance(const ls::ref::Ray& ray) const;

    [[nodiscard]] const PixelCamera& camera() const { return camera_; }
    [[nodiscard]] const Bvh& bvh() const { return bvh_; }
    // The scene's lights in its order ("light", or "lights"); never empty.
    [[nodiscard]] const std::vector<ls::ref::Light>& lights() const { return lights_; }
    [[nodiscard]] const ls::ref::Light& light() const { return lights_.front(); }
    [[nodiscard]] const ls::ref::Medium& medium() const { return medium_; }
    [[nodiscard]] const ReferenceOptions& options() const { return options_; }

    // A light's cookie: linear RGB texels and the host's projection; width 0: none.
    struct Cookie {
        uint32_t width = 0, height = 0;
        std::vector<glm::dvec3> linear;  // row 0 at the top (v = 0)
        glm::dmat4 projection{1.0};
        [[nodiscard]] glm::dvec3 at(const glm::dvec3& p) const;
    };

  private:
    PixelCamera camera_;
    Bvh bvh_;
    std::vector<ls::ref::Light> lights_;
    std::vector<Cookie> cookies_;  // one per light
    ls::ref::Medium medium_;
    ReferenceOptions options_;
};

// Lin per pixel centre, rows shared among `threads` threads. Each pixel depends on nothing but its
// own ray, so the image is the same bit for bit for any thread count. `progress` is called with
// the fraction of rows done, never decreasing, from the worker threads (one call at a time), and
// last with exactly 1 from the calling thread. An exception in a worker is rethrown here.
[[nodiscard]] ReferenceImage renderReference(const SceneDesc& scene, const MeshData& mesh,
                                             uint32_t width, uint32_t height,
                                             const ReferenceOptions& options = {},
                                             std::function<void(double fraction)> progress = {});

}  // namespace host::reference
