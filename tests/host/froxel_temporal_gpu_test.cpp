// The froxels' temporal mode against the float64 reference (lavapipe, validation), at the
// benchmark's 160x90 (bench/froxels_flicker.json): on a still scene the settled grid is closer to
// the reference than the plain grid, which takes each froxel's shadow at one point; and a light
// that jumps leaves no ghost of where it was, the frame after the jump about as close to the
// reference as the plain grid's. Each bound is one a blend that keeps no history, or one that
// keeps it where the light left, fails (the figures measured with each are beside the bounds).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "bench/flicker.h"
#include "bench/motion.h"
#include "engine_renderer.h"
#include "exact_renderer/reference_renderer.h"
#include "support/gpu_test.h"

#include <glm/glm.hpp>

namespace {

const VkExtent2D kSize{160, 90};

host::SceneDesc shippedScene(const std::string& name) {
    return host::loadSceneFile(std::string(LS_SOURCE_DIR) + "/scenes/" + name + ".json");
}

// sum |Lin - reference| / sum |reference| over every pixel and channel.
double meanRelative(const std::vector<float>& rgba, const std::vector<double>& ref) {
    double diff = 0, sum = 0;
    for (size_t p = 0; p < ref.size() / 3; ++p)
        for (size_t c = 0; c < 3; ++c) {
            EXPECT_TRUE(std::isfinite(rgba[p * 4 + c]));
            diff += std::fabs(double(rgba[p * 4 + c]) - ref[p * 3 + c]);
            sum += std::fabs(ref[p * 3 + c]);
        }
    return diff / sum;
}

std::vector<double> reference(const host::SceneDesc& scene, const host::MeshData& mesh) {
    return host::reference::renderReference(scene, mesh, kSize.width, kSize.height).rgb;
}

// A froxel preset's grid (tile 8: froxels-hdrp, 16: froxels-unreal), plain or temporal, and with
// the temporal mode's still frames refined per pixel.
host::RenderOptions froxels(uint32_t tile, bool temporal, bool pixels = false) {
    host::RenderOptions o;
    o.method = lightscatter::Method::Froxels;
    o.custom.froxels.tile = tile;
    o.custom.froxels.temporal = temporal;
    o.custom.froxels.pixelHistory = pixels;
    return o;
}

// The mean error of frames 17 to 24 after a reset (a still scene: the history settled).
double settledError(host::EngineRenderer& renderer, host::RenderOptions options,
                    const std::vector<double>& ref) {
    options.resetHistory = true;
    double sum = 0;
    for (int frame = 1; frame <= 24; ++frame) {
        const std::vector<float> lin = renderer.render(options).inscatter;
        options.resetHistory = false;
        if (frame > 16) sum += meanRelative(lin, ref) / 8;
    }
    return sum;
}

// 16 still frames after a reset, refined per pixel at HDRP's 8-pixel columns: the options the
// frames after them keep rendering with, and the last frame's Lin.
std::pair<host::RenderOptions, std::vector<float>> gatherStill(host::EngineRenderer& renderer) {
    host::RenderOptions o = froxels(8, true, true);
    o.resetHistory = true;
    std::vector<float> lin;
    for (int frame = 0; frame < 16; ++frame) {
        lin = renderer.render(o).inscatter;
        o.resetHistory = false;
    }
    return {o, lin};
}

}  // namespace

class FroxelTemporalGpu : public testing_support::GpuTest {};

// window_room at Unreal's 16-pixel columns: the spot's shafts through the grille cross each slice
// of a column's ray in and out of shadow, and the plain grid takes each slice's shadow at one
// point (the lit part's middle). The temporal mode moves that point along the slice from frame
// to frame and the blend settles on the average: frames 17 to 24 measured 0.455 off on average
// against the plain grid's 0.509. The same frames without the history (its weight 0: each frame's
// own points alone) measured 0.515, worse than the plain grid, and fail the bound.
TEST_F(FroxelTemporalGpu, AStillSceneSettlesCloserToTheReferenceThanThePlainGrid) {
    const host::SceneDesc scene = shippedScene("window_room");
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    const std::vector<double> ref = reference(scene, mesh);
    host::EngineRenderer renderer(dev(), scene, mesh, kSize);
    const double plain = meanRelative(renderer.render(froxels(16, false)).inscatter, ref);
    // With the history's weight given.
    auto settled = [&](float weight) {
        host::RenderOptions temporal = froxels(16, true);
        temporal.custom.froxels.historyWeight = weight;
        return settledError(renderer, temporal, ref);
    };
    const double blended = settled(0.9f), alone = settled(0.0f);
    std::printf(
        "window_room, 16-pixel columns: plain %.4f, temporal %.4f, without its history "
        "%.4f\n",
        plain, blended, alone);
    EXPECT_LT(blended, 0.93 * plain);
    EXPECT_LT(alone, 1.1 * plain) << "each frame's own points are no worse than a noisy plain grid";
}

namespace {

// atrium's sun turned by `degrees` about the vertical between two frames (the camera stays), after
// 24 frames that settled the history on the shafts where they were: the frame after the turn's
// error against the reference of the new pose, and the plain grid's.
std::pair<double, double> afterTurn(rg::Device& device, float degrees) {
    host::SceneDesc scene = shippedScene("atrium");
    EXPECT_EQ(scene.light.type, lightscatter::LightType::Directional);
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    host::EngineRenderer renderer(device, scene, mesh, kSize);
    const host::RenderOptions temporal = froxels(8, true);
    for (int frame = 1; frame <= 24; ++frame) (void)renderer.render(temporal);
    // The shafts through the roof sweep across the floor.
    const glm::vec3 d = scene.light.direction;
    const float a = glm::radians(degrees);
    scene.light.direction = glm::normalize(glm::vec3(d.x * std::cos(a) - d.z * std::sin(a), d.y,
                                                     d.x * std::sin(a) + d.z * std::cos(a)));
    renderer.scene().light = scene.light;
    const std::vector<double> ref = reference(scene, mesh);
    const double turned = meanRelative(renderer.render(temporal).inscatter, ref);
    host::EngineRenderer fresh(device, scene, mesh, kSize);
    const double plain = meanRelative(fresh.render(froxels(8, false)).inscatter, ref);
    std::printf("atrium, sun turned %.1f degrees: plain %.4f, temporal the frame after %.4f\n",
                degrees, plain, turned);
    return {turned, plain};
}

}  // namespace

// A turn of 10 degrees is a jump (PreviousFrame::lightJump over the 1 degree that drops the
// history): the frame after is its own points alone, measured 1.18 times the plain grid's error.
// The history kept (clamped to this frame's neighbourhood, which the roof's dense shafts span, so
// it clamps little) draws the old shafts at nine tenths: measured 5.4 times (6.2 without the
// clamp either).
TEST_F(FroxelTemporalGpu, ALightThatJumpsLeavesNoGhost) {
    const auto [jumped, plain] = afterTurn(dev(), 10.0f);
    EXPECT_LT(jumped, 1.3 * plain);
}

// point_fog's unshadowed point light moving 2 cm a frame to the camera's right
// (bench/flicker.json's light motion, below the jump that drops the history), at froxels-hdrp's
// size, 24 frames into the motion after 16 still ones: the slab's unshadowed in-scattering is exact
// in every frame, so the history, carried to this frame's unshadowed value before the blend, leaves
// no trail of the glow where the light was. Measured: the temporal mode's error 1.00 times the
// plain grid's at the same pose; with the history blended as it is (not carried), 1.13 times.
TEST_F(FroxelTemporalGpu, AMovingLightsGlowLeavesNoTrail) {
    const host::SceneDesc start = shippedScene("point_fog");
    ASSERT_NE(start.light.type, lightscatter::LightType::Directional);
    const host::MeshData mesh = host::loadSceneMeshes(start);
    host::EngineRenderer renderer(dev(), start, mesh, kSize);
    host::bench::Motion motion;
    host::RenderOptions temporal = froxels(8, true);
    temporal.resetHistory = true;
    for (int frame = 0; frame < 16 + 24; ++frame) {
        renderer.scene().light = host::bench::poseAt(start, host::bench::MotionKind::Light, motion,
                                                     std::max(frame - 16, 0))
                                     .light;
        const std::vector<float> lin = renderer.render(temporal).inscatter;
        temporal.resetHistory = false;
        if (frame + 1 < 16 + 24) continue;
        const std::vector<double> ref = reference(renderer.scene(), mesh);
        host::EngineRenderer fresh(dev(), renderer.scene(), mesh, kSize);
        const double moving = meanRelative(lin, ref);
        const double plain = meanRelative(fresh.render(froxels(8, false)).inscatter, ref);
        std::printf("point_fog, light moving 24 frames: plain %.5f, temporal %.5f (%.3fx)\n", plain,
                    moving, moving / plain);
        EXPECT_LT(moving, 1.03 * plain);
    }
}

// engine_spot at HDRP's 8-pixel columns: the spot's struts cast shadows thinner than a column,
// which a trilinear fetch between the columns' rays spreads over the froxel. With the per-pixel
// history the still frames step the columns across a froxel and each pixel gathers the rays that
// pass nearest it: frames 17 to 24 after a reset measured 0.233 of the plain grid's error. The
// temporal mode without it (each pixel's trilinear fetch of a blended grid) measured 1.006, and
// fails the bound.
TEST_F(FroxelTemporalGpu, StillFramesGatheredPerPixelResolveFinerThanAFroxel) {
    const host::SceneDesc scene = shippedScene("engine_spot");
    const host::MeshData mesh = host::loadSceneMeshes(scene);
    const std::vector<double> ref = reference(scene, mesh);
    host::EngineRenderer renderer(dev(), scene, mesh, kSize);
    const double plain = meanRelative(renderer.render(froxels(8, false)).inscatter, ref);
    const double gathered = settledError(renderer, froxels(8, true, true), ref);
    const double temporal = settledError(renderer, froxels(8, true, false), ref);
    std::printf(
        "engine_spot, 8-pixel columns, still: plain %.4f, per pixel %.4f (%.3fx), "
        "temporal %.4f (%.3fx)\n",
        plain, gathered, gathered / plain, temporal, temporal / plain);
    EXPECT_LT(gathered, 0.4 * plain);
    EXPECT_GT(temporal, 0.4 * plain) << "the bound is one the temporal mode alone does not meet";
}

// After 16 still frames gathered per pixel, the camera moves at once by ten of bench/flicker.json's
// steps (20 cm and a degree: about three pixels at this size). The detail each pixel gathered
// corrects the grid's fetch where its columns were, which stay on the screen while the surface
// moves, so a pixel that moved far keeps little of it: no trail of the old pose. Measured: 1.025
// of the plain grid's error (1.051 while the grid the still frames held their detail against was
// the first frame's jittered one); 1.032 for a restart from the trilinear fetch (the behaviour
// before); 1.437 with the detail carried whole wherever the surface went.
TEST_F(FroxelTemporalGpu, AFrameThatMovedFarLeavesNoTrailOfTheGatheredPixels) {
    const host::SceneDesc start = shippedScene("engine_spot");
    const host::MeshData mesh = host::loadSceneMeshes(start);
    host::EngineRenderer renderer(dev(), start, mesh, kSize);
    host::bench::Motion motion;
    const host::RenderOptions o = gatherStill(renderer).first;
    renderer.scene().camera =
        host::bench::poseAt(start, host::bench::MotionKind::Camera, motion, 10).camera;
    const std::vector<float> lin = renderer.render(o).inscatter;
    const std::vector<double> ref = reference(renderer.scene(), mesh);
    host::EngineRenderer fresh(dev(), renderer.scene(), mesh, kSize);
    const double moved = meanRelative(lin, ref);
    const double plain = meanRelative(fresh.render(froxels(8, false)).inscatter, ref);
    std::printf(
        "engine_spot, camera moved 10 steps after 16 still frames: plain %.4f, per pixel %.4f "
        "(%.3fx)\n",
        plain, moved, moved / plain);
    EXPECT_LT(moved, 1.1 * plain);
}

// The first frame that moves after still ones keeps the image the still frames gathered, less
// the motion: bench/flicker.json's first camera step changes engine_spot's Lin by 0.0268 of the
// reference's mean, where the reference itself changes by 0.0249. A restart from the trilinear
// fetch (the behaviour before) changed it by 0.0827: the jump from the gathered image to the
// grid's, a flicker at every start of a motion, fails the bound.
TEST_F(FroxelTemporalGpu, TheFirstFrameThatMovesKeepsTheGatheredImage) {
    const host::SceneDesc start = shippedScene("engine_spot");
    const host::MeshData mesh = host::loadSceneMeshes(start);
    host::EngineRenderer renderer(dev(), start, mesh, kSize);
    host::bench::Motion motion;
    const auto [o, still] = gatherStill(renderer);
    const std::vector<double> before = reference(renderer.scene(), mesh);
    renderer.scene().camera =
        host::bench::poseAt(start, host::bench::MotionKind::Camera, motion, 1).camera;
    const std::vector<float> moved = renderer.render(o).inscatter;
    const std::vector<double> after = reference(renderer.scene(), mesh);
    double change = 0, refChange = 0, sum = 0;
    for (size_t p = 0; p < after.size() / 3; ++p)
        for (size_t c = 0; c < 3; ++c) {
            change += std::fabs(double(moved[p * 4 + c]) - still[p * 4 + c]);
            refChange += std::fabs(after[p * 3 + c] - before[p * 3 + c]);
            sum += std::fabs(after[p * 3 + c]);
        }
    std::printf(
        "engine_spot, first camera step after 16 still frames: Lin changed by %.4f, the "
        "reference by %.4f\n",
        change / sum, refChange / sum);
    EXPECT_LT(change, 1.5 * refChange);
}

namespace {

// A scene under one of bench/flicker.json's motions, `frames` frames after 16 still ones: its
// pose in each frame, and the float64 reference of each frame judged, from frame `firstPair` of
// the motion on (0: the last still frame, so the first pair is the motion's start). The
// references serve every configuration rendered along it.
struct MotionRun {
    host::SceneDesc start;
    host::MeshData mesh;
    host::bench::MotionKind kind;
    int frames, firstPair;
    std::vector<std::vector<double>> refs;

    MotionRun(const std::string& scene, host::bench::MotionKind k, int n, int first)
        : start(shippedScene(scene)),
          mesh(host::loadSceneMeshes(start)),
          kind(k),
          frames(n),
          firstPair(first) {
        for (int frame = 15 + firstPair; frame < 16 + frames; ++frame)
            refs.push_back(reference(pose(frame), mesh));
    }
    [[nodiscard]] host::SceneDesc pose(int frame) const {
        return host::bench::poseAt(start, kind, host::bench::Motion{}, std::max(frame - 15, 0));
    }
};

// Along `run`, with the froxels' `tile`: the excess flicker (what the image changes by beyond the
// reference's change, FlickerMeter) over its judged frames, and the mean error of the moving
// frames, for the plain grid or the temporal mode with the per-pixel history.
std::pair<double, double> underMotion(rg::Device& device, const MotionRun& run, uint32_t tile,
                                      bool pixels) {
    host::EngineRenderer renderer(device, run.start, run.mesh, kSize);
    host::RenderOptions o = froxels(tile, pixels, pixels);
    o.resetHistory = true;
    host::bench::FlickerMeter meter;
    double error = 0;
    for (int frame = 0; frame < 16 + run.frames; ++frame) {
        const host::SceneDesc pose = run.pose(frame);
        renderer.scene().light = pose.light;
        renderer.scene().camera = pose.camera;
        const std::vector<float> lin = renderer.render(o).inscatter;
        o.resetHistory = false;
        if (frame < 15 + run.firstPair) continue;
        const std::vector<double>& ref = run.refs[size_t(frame - 15 - run.firstPair)];
        meter.add(lin, ref);
        if (frame > 15) error += meanRelative(lin, ref) / run.frames;
    }
    return {meter.result().meanExcess, error};
}

// The per-pixel history's excess flicker and error under that motion, each over the plain grid's.
std::pair<double, double> againstPlainGrid(rg::Device& device, const std::string& scene,
                                           host::bench::MotionKind kind, uint32_t tile, int frames,
                                           int firstPair) {
    const MotionRun run(scene, kind, frames, firstPair);
    const auto [plainFlicker, plainError] = underMotion(device, run, tile, false);
    const auto [flicker, error] = underMotion(device, run, tile, true);
    std::printf(
        "%s, %s moving %d frames, %u-pixel columns: plain flicker %.5f error %.4f, per pixel "
        "flicker %.5f (%.3fx) error %.4f (%.3fx)\n",
        scene.c_str(), host::bench::motionName(kind), frames, tile, plainFlicker, plainError,
        flicker, flicker / plainFlicker, error, error / plainError);
    return {flicker / plainFlicker, error / plainError};
}

}  // namespace

// While a light moves and the camera does not, the per-pixel history's grid takes each froxel at
// its centre, as the plain grid, and each pixel keeps the detail it gathered while still where the
// grid's own change hides it (docs/methods.md, "Still frames refined per pixel"), so the image
// moves about as the plain grid's does, closer to the reference. Measured over 24 frames of the
// atrium's turning sun: excess flicker 1.09x the plain grid's and error 0.61x; the jittered,
// blended grid with the detail fading 3% a frame (the mode before) 2.00x and 0.72x, and fails.
TEST_F(FroxelTemporalGpu, UnderAMovingLightThePixelsMoveAsThePlainGrid) {
    const auto [flicker, error] =
        againstPlainGrid(dev(), "atrium", host::bench::MotionKind::Light, 16, 24, 0);
    EXPECT_LT(flicker, 1.2);
    EXPECT_LT(error, 0.9);
}

// While the camera moves, each pixel also gathers this frame's nearest column into what it showed
// (apply.comp, kMovingMemory), so the detail follows the scene sliding under the columns instead of
// going stale. point_fog's glow at HDRP's 8-pixel columns, bench/flicker.json's camera motion, its
// 60 frames' 59 pairs as the bench judges them: excess flicker 1.01x the plain grid's and error
// 0.95x. With the detail carried and faded within the limit alone (the mode before), 1.09x: it
// fails.
TEST_F(FroxelTemporalGpu, UnderAMovingCameraThePixelsGatherAndFlickerAsThePlainGrid) {
    const auto [flicker, error] =
        againstPlainGrid(dev(), "point_fog", host::bench::MotionKind::Camera, 8, 60, 1);
    EXPECT_LT(flicker, 1.04);
    EXPECT_LT(error, 1.0);
}
