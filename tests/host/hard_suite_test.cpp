// The hard-case suite (scenes/hard, made by tools/make_scenes/make_hard_cases.py): every case,
// every method, at 64x36 with the balanced profile, against the float64 reference with exact
// visibility. Each must give finite pixels and stay within the bound docs/performance.md states for
// it (mean relative error of Lin, sum |a - b| / sum |b|); thin media within 1% of float64.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "bench/metrics.h"
#include "engine_renderer.h"
#include "exact_renderer/reference_renderer.h"
#include "support/gpu_test.h"

namespace {

struct Bound {
    double epipolar, bruteForce;
    double coneMarch = 1.0, analytic = 1.0;
};

// Measured on lavapipe (see docs/performance.md), with room for driver differences. Where the
// epipolar bound is loose the error is interpolation along too few samples of a 64-pixel line
// (an initial step of 16); brute force's is the shadow map's. cone-march (32 samples per pixel,
// midpoints) misses the peak of 1/r^2 where a ray passes through or starts at a light: measured
// 0.69 (point_at_camera), 0.64 (spot_at_camera), 0.10 (ray_through_point_light), 0.025
// (sun_into_view), 0.010 (shadow_map_not_pow2), at most 0.0034 elsewhere. analytic (seed 001) runs
// on the unshadowed point-light cases only, where it ignores the medium's Mie lobe and extinction:
// measured 1.75 (point_at_camera) and 0.48 (ray_through_point_light), which docs/methods.md
// explains; the bounds hold the error where it is, so that a regression shows.
const std::map<std::string, Bound> kBounds = {
    {"spot_at_camera", {0.22, 0.045, 0.9}},
    {"point_at_camera", {0.045, 0.045, 0.9, 2.3}},
    {"sun_into_view", {0.09, 0.036, 0.04}},
    {"dense_medium", {0.08, 0.015, 0.015}},
    {"reversed_z", {0.09, 0.015, 0.015}},
    {"reversed_infinite", {0.09, 0.015, 0.015}},
    {"zero_extinction_channel", {0.09, 0.015, 0.015}},
    {"shadow_map_not_pow2", {0.10, 0.017, 0.02}},
    {"light_center", {0.03, 0.01, 0.015}},
    {"thin_medium_km", {0.01, 0.01, 0.01}},
    {"ray_through_point_light", {0.02, 0.01, 0.15, 0.65}},
    // A sun 3 degrees above a city 20 km deep, reversed depth (issue #22: refused as a singular
    // shadow matrix). Measured 0.0005 epipolar, 0.0006 brute-force, 0.0009 cone-march; the same
    // frame without its shadows is 0.020 off, so the bounds hold the shadows.
    {"low_sun_city", {0.002, 0.002, 0.003}},
    // A cube-shadowed point light on screen in a small cage, seen through a gap with a bar behind
    // it: measured 0.0134 epipolar (0.0284 before the light's first samples were spaced like their
    // distance from it, docs/epipolar.md), 0.0082 brute force.
    {"point_in_cage", {0.016, 0.0095}},
    // The same cage from 6 m, its bars a pixel wide at 320x180 and under a pixel here: measured
    // 0.0145 epipolar, 0.0055 brute force (at 320x180 0.0080 and 0.0059, docs/epipolar.md).
    {"point_in_small_cage", {0.018, 0.0075}},
    // Issue #25's shapes, each the sibling of an older case: a soft spot (inner 10, outer 35
    // degrees) where light_center's hard one is, measured 0.0212 epipolar, 0.0004 brute force,
    // 0.0003 cone-march; a windowed point light (range 3 m) on a pixel's ray as in
    // ray_through_point_light, measured 0.0005 epipolar and brute force, 0.053 cone-march, 0.53
    // analytic.
    {"soft_spot_center", {0.03, 0.01, 0.015}},
    {"windowed_point_on_ray", {0.02, 0.01, 0.08, 0.65}},
};
constexpr Bound kDefault{0.02, 0.01, 0.015, 1.0};

// planes (seed 002, balanced: 128 planes into a float16 target) samples each ray at the planes'
// midpoints from the near plane on: it misses the head of a ray that starts at a light (measured
// 0.855 point_at_camera, 0.787 spot_at_camera), and the peak of 1/r^2 between two planes beside a
// light (0.26 light_on_edge, 0.16 light_corner, 0.14 light_center, 0.135 dense_medium, 0.109
// ray_through_point_light), at most 0.076 elsewhere (docs/methods.md).
const std::map<std::string, double> kPlanesBounds = {
    {"point_at_camera", 1.0},
    {"spot_at_camera", 0.95},
    {"light_on_edge", 0.32},
    {"light_corner", 0.2},
    {"light_center", 0.17},
    {"dense_medium", 0.17},
    {"ray_through_point_light", 0.14},
    {"windowed_point_on_ray", 0.18},  // measured 0.142, as ray_through_point_light
    {"thin_medium_km", 0.002},
    {"low_sun_city", 0.05},  // measured 0.025: 128 planes across 20 km
};
constexpr double kPlanesDefault = 0.1;

// beam-tree-analytic (seed 004, a box per connected part of the glTF's primitives as occluders)
// integrates the lit space in closed form, which on these cases is nearly all the light's volume in
// view; the uncertain space behind the boxes is sampled by seed 002's planes. Measured 0.0296
// point_at_camera, 0.0273 spot_at_camera (planes near the light, behind a box), 0.009 light_center,
// at most 0.0016 elsewhere.
const std::map<std::string, double> kBeamTreeBounds = {
    {"point_at_camera", 0.045},
    {"spot_at_camera", 0.04},
    {"light_center", 0.015},
};
constexpr double kBeamTreeDefault = 0.005;

// beam-tree-sampling (seed 004 5.3) draws seed 002's planes where the tree says lit or uncertain
// (float32 target), with thinner planes near the light's depth whose slabs take the closed form
// (planes.frag); the frontmost slab also takes the ray's head before the planes' box, and a
// shadowed spot's slabs beside its apex are drawn over every ray that crosses its cone within
// them. Measured: 0.0294 point_at_camera and 0.0273 spot_at_camera (brute force 0.0291 and
// 0.0290: 0.755 and 0.732 when the head was left out, the light's glow lying before the first
// plane), 0.0104 light_on_edge and 0.0140 light_corner (0.0529 and 0.0315 with those slabs cut to
// the cone at their planes' depths, which lost the rays crossing it beside its apex), 0.049
// light_behind_camera, at most 0.043 elsewhere (before the near planes: 0.263 light_on_edge, 0.161
// light_corner, 0.142 light_center, 0.134 dense_medium, 0.144 windowed_point_on_ray).
const std::map<std::string, double> kBeamTreeSamplingBounds = {
    {"point_at_camera", 0.045},
    {"spot_at_camera", 0.045},
    {"light_on_edge", 0.02},
    {"light_corner", 0.02},
    {"thin_medium_km", 0.002},
    // Measured 0.0547 and 0.0558 (0.214 and 0.124 at 320x180 with even planes and midpoints; 0.057
    // and 0.058 now, bench/point_in_cage_sampling.json).
    {"point_in_cage", 0.08},
    {"point_in_small_cage", 0.08},
};
constexpr double kBeamTreeSamplingDefault = 0.06;

// froxels (2-pixel columns, 64 slices: froxels-hdrp's density at 1920x1080) spread a froxel's
// in-scattering over the froxel, so thin shafts (the grille's) and a soft cone's edge are off by
// tens of percent; the error falls as the grid refines. A point or spot light's froxel takes its
// slice of the column's ray in closed form (inject.comp's LS_SLAB), so a froxel at or beside the
// light gives the energy it holds: point_at_camera 0.029, spot_at_camera 0.089, light_on_edge
// 0.195 (a point sample per froxel: 0.546, 0.538 and 0.624, which these bounds refuse). Measured on
// lavapipe: 0.501 dense_medium, 0.368 soft_spot_center, 0.345 reversed_z, reversed_infinite,
// shadow_map_not_pow2 and zero_extinction_channel, 0.318 light_center, 0.193
// windowed_point_on_ray, 0.182 point_in_small_cage, 0.180 sky_far_plane, 0.140 light_corner, 0.118
// ray_through_point_light, 0.094 point_in_cage, 0.036 sun_into_view, at most 0.0101 elsewhere (a
// black image is 1.0 off everywhere).
const std::map<std::string, double> kFroxelBounds = {
    {"light_on_edge", 0.25},       {"dense_medium", 0.58},
    {"point_at_camera", 0.05},     {"spot_at_camera", 0.12},
    {"reversed_z", 0.40},          {"reversed_infinite", 0.40},
    {"shadow_map_not_pow2", 0.40}, {"zero_extinction_channel", 0.40},
    {"soft_spot_center", 0.42},    {"light_center", 0.37},
    {"sky_far_plane", 0.21},       {"windowed_point_on_ray", 0.23},
    {"light_corner", 0.17},        {"ray_through_point_light", 0.14},
    {"point_in_cage", 0.11},       {"sun_into_view", 0.042},
    {"point_in_small_cage", 0.21},
};
constexpr double kFroxelDefault = 0.012;

}  // namespace

class HardSuite : public testing_support::GpuTest {};

TEST_F(HardSuite, EveryCaseIsFiniteAndWithinItsBound) {
    const VkExtent2D size{64, 36};
    size_t cases = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(LS_SOURCE_DIR) + "/scenes/hard")) {
        if (entry.path().extension() != ".json") continue;
        const std::string name = entry.path().stem().string();
        const host::SceneDesc scene = host::loadSceneFile(entry.path().string());
        const host::MeshData mesh = host::loadSceneMeshes(scene);
        const auto reference =
            host::reference::renderReference(scene, mesh, size.width, size.height);
        host::EngineRenderer renderer(dev(), scene, mesh, size);
        const Bound bound = kBounds.count(name) ? kBounds.at(name) : kDefault;
        for (lightscatter::Method method :
             {lightscatter::Method::Epipolar, lightscatter::Method::BruteForce,
              lightscatter::Method::ConeMarch, lightscatter::Method::Analytic,
              lightscatter::Method::Planes, lightscatter::Method::BeamTreeAnalytic,
              lightscatter::Method::BeamTreeSampling, lightscatter::Method::Froxels}) {
            // Seed 001's closed form only takes unshadowed point and spot lights (refusals: Cli
            // tests).
            const bool unshadowedPointLike = scene.light.type == lightscatter::LightType::Point ||
                                             (scene.light.type == lightscatter::LightType::Spot &&
                                              scene.light.shadowMapSize == 0);
            if (method == lightscatter::Method::Analytic && !unshadowedPointLike) continue;
            // A point light's cube shadow map (the caged lights): bounded here for epipolar, brute
            // force, froxels and beam-tree-sampling (the 10% at 320x180); cone-march,
            // planes and beam-tree-analytic sample it too, without a bound in this suite yet.
            const bool cubeShadowed =
                scene.light.type == lightscatter::LightType::Point && scene.light.shadowMapSize > 0;
            if (cubeShadowed && method != lightscatter::Method::Epipolar &&
                method != lightscatter::Method::BruteForce &&
                method != lightscatter::Method::Froxels &&
                method != lightscatter::Method::BeamTreeSampling)
                continue;
            // Seed 004's beam tree is built from a point or spot light.
            if ((method == lightscatter::Method::BeamTreeAnalytic ||
                 method == lightscatter::Method::BeamTreeSampling) &&
                scene.light.type == lightscatter::LightType::Directional)
                continue;
            host::RenderOptions options;
            options.method = method;
            // Froxels of 2 pixels: 32 columns across 64, the density of froxels-hdrp's 240 across
            // 1920.
            options.custom.froxels.tile = 2;
            const host::FrameOutput out = renderer.render(options);
            const auto e =
                host::bench::compareToReference(out.inscatter, reference.rgb, scene.exposure);
            for (float v : out.color) ASSERT_TRUE(std::isfinite(v)) << name;
            EXPECT_EQ(e.nonFinite, 0u) << name;
            std::printf("%-26s %-12s %8.4f\n", name.c_str(), lightscatter::methodName(method),
                        e.meanRelative);
            const double limit =
                method == lightscatter::Method::Epipolar     ? bound.epipolar
                : method == lightscatter::Method::BruteForce ? bound.bruteForce
                : method == lightscatter::Method::ConeMarch  ? bound.coneMarch
                : method == lightscatter::Method::Analytic   ? bound.analytic
                : method == lightscatter::Method::BeamTreeAnalytic
                    ? (kBeamTreeBounds.count(name) ? kBeamTreeBounds.at(name) : kBeamTreeDefault)
                : method == lightscatter::Method::BeamTreeSampling
                    ? (kBeamTreeSamplingBounds.count(name) ? kBeamTreeSamplingBounds.at(name)
                                                           : kBeamTreeSamplingDefault)
                : method == lightscatter::Method::Froxels
                    ? (kFroxelBounds.count(name) ? kFroxelBounds.at(name) : kFroxelDefault)
                : kPlanesBounds.count(name) ? kPlanesBounds.at(name)
                                            : kPlanesDefault;
            EXPECT_LE(e.meanRelative, limit)
                << name << " (" << lightscatter::methodName(method) << ")";
            if (method != lightscatter::Method::Epipolar) continue;
            // Refinement on in-scattering differences (docs/epipolar.md): within the same bound,
            // and never worse than without it (measured: 8 cases better, the others unchanged).
            // The profile (balanced) takes the threshold from `custom`.
            host::RenderOptions refined = options;
            refined.custom.epipolar.inscatterRefinementThreshold = 0.1f;
            const auto r = host::bench::compareToReference(renderer.render(refined).inscatter,
                                                           reference.rgb, scene.exposure);
            std::printf("%-26s %-12s %8.4f (refinement 0.1)\n", name.c_str(), "epipolar",
                        r.meanRelative);
            EXPECT_EQ(r.nonFinite, 0u) << name << " (refinement)";
            EXPECT_LE(r.meanRelative, limit) << name << " (epipolar, refinement)";
            EXPECT_LE(r.meanRelative, e.meanRelative * 1.01 + 1e-4)
                << name << " (epipolar, refinement)";
        }
        ++cases;
    }
    EXPECT_GE(cases, 20u);
}
