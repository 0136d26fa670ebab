#include "froxel_nodes.h"

#include "froxel_shaders.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "apply_comp_variants.h"
#include "export_comp.h"
#include "inject_comp_variants.h"
#include "integrate_comp_variants.h"
#include "shaders/froxels/froxel_bindings.h"
#include "shared/pass_helpers.h"
#include "shared/shader_variant.h"
#include "temporal_comp.h"

namespace ls {
namespace {

// The passes that take one froxel per invocation (the point-sampled injection, the temporal blend,
// the volume export) run groups of 32 x 4 froxels of one slice, their shaders' local size.
void dispatchPerFroxel(rg::PassContext& ctx, uint32_t columns, uint32_t rows, uint32_t slices) {
    ctx.vk().CmdDispatch(ctx.cmd(), groupCount(columns, 32), groupCount(rows, 4), slices);
}

// The froxel passes' push block (its fields written once, in froxel_push_fields.h).
struct FroxelPush {
#define LS_VEC4 glm::vec4
#include "shaders/froxels/froxel_push_fields.h"
#undef LS_VEC4
};

// The push block of a frame: the slices from the near plane to the far distance, capped by the
// medium's maxDistance and a finite far plane (no ray goes further); Lin stored at `storage`.
FroxelPush froxelPush(const FrameConstants& c, const FroxelGrid& g, float storage) {
    const FroxelDepthRange z = froxelDepthRange(c.depthInfo.z, c.depthInfo.w, c.depthInfo.y > 0.5f,
                                                c.betaM.w, g.farDistance);
    FroxelPush p{};
    p.grid = {float(g.columns), float(g.rows), float(g.slices), float(g.tile)};
    p.slices = {z.nearZ, z.farZ, std::log(z.farZ / z.nearZ), storage};
    p.jitter = glm::vec4(0.5f);
    p.columns = {0.0f, 0.0f, float(g.columns), float(g.rows)};
    p.shift = {0.0f, 0.0f, 1.0f, 0.0f};
    return p;
}

// A still frame of the per-pixel history: the columns move by the step of its age, and each
// froxel's own point stays on its column's ray.
FroxelColumns stepColumns(FroxelPush& push, const rg::PassContext& ctx,
                          const FroxelPixelClock& clock, const FrameConstants& now) {
    const FroxelColumns c = froxelColumns(ctx, clock, now);
    if (c.still) push.shift = glm::vec4(c.shift, 0.0f, 1.0f);
    return c;
}

// apply.comp's push block (froxel_apply_push_fields.h).
struct FroxelApplyPush {
#define LS_VEC4 glm::vec4
#define LS_MAT4 glm::mat4
#include "shaders/froxels/froxel_apply_push_fields.h"
#undef LS_VEC4
#undef LS_MAT4
};
static_assert(sizeof(FroxelApplyPush) <= 128, "Vulkan guarantees 128 bytes of push constants");

// temporal.comp's push block (froxel_temporal_push_fields.h).
struct FroxelTemporalPush {
#define LS_VEC4 glm::vec4
#define LS_MAT4 glm::mat4
#include "shaders/froxels/froxel_temporal_push_fields.h"
#undef LS_VEC4
#undef LS_MAT4
};
static_assert(sizeof(FroxelTemporalPush) <= 128, "Vulkan guarantees 128 bytes of push constants");

// The temporal mode's points spread over the middle half of each froxel along each axis, not the
// whole of it: the apply's trilinear fetch already spreads a froxel's value over the froxels on
// either side, and the whole froxel's average blurred the shafts more than it took off the plain
// grid's aliasing on the bench's still scenes (docs/methods.md, "The temporal mode").
constexpr float kJitterSpread = 0.5f;
// Where a light changed, a history this many widths of this frame's neighbourhood range outside
// it is dropped: further than the jitter can take a froxel's samples.
constexpr float kDropOutside = 1.0f;
// A light that moved or turned by more than this (PreviousFrame::lightJump; radians, 1 degree)
// drops the whole history, as a camera cut does: its shafts are elsewhere, and where they are as
// dense as a roof's slats, this frame's neighbourhood spans the old ones too and clamps nothing.
// A light animated slowly moves far less a frame (bench/flicker.json's: 0.1 degree, or 2 cm).
constexpr float kLightJump = 0.0175f;

// In a frame where the camera moved, the history is resampled where the frame before saw each
// froxel, and each resampling blurs it a little: there its memory, 1 / (1 - weight) frames, is cut
// this many times (10 frames to 4 at the default weight), so that fewer resamplings add up. The
// camera's motion is where the plain grid flickers most, so the noise a lighter history lets
// through costs little there; under a moving light it does not, and the weight stays (the
// weights tried: docs/methods.md, "The temporal mode").
constexpr float kMovingCameraMemory = 2.5f;
float movingCameraWeight(float weight) {
    return std::max(0.0f, 1.0f - kMovingCameraMemory * (1.0f - weight));
}

// The per-pixel history: a pixel weighs this frame's nearest column by a Gaussian of its distance
// to the column's ray, of this width (sigma, froxels), and the history carries at most this much
// weight (a pixel gathers about 2 pi 0.15^2 = 0.14 a frame: about a hundred frames). A frame that
// moved seeds each pixel with its trilinear fetch at the last weight, a fallback the first rays
// gathered outweigh. On bench/froxels_pixels.json's still frames (docs/methods.md) a wider
// Gaussian (0.25) blurred the shafts and a shorter memory (4) flickered.
constexpr float kPixelWidth = 0.15f;
constexpr float kPixelWeight = 16.0f;
constexpr float kPixelSeed = 0.1f;

// In a frame that moved, each pixel keeps this share of the detail it had (what it gathered
// against the grid's fetch), carried from where the frame before saw its surface (apply.comp
// keeps less the further the surface moved) and clamped as a still frame's gathering is. The
// detail fades over some thirty frames rather than dropping at the first that moves: on
// bench/froxels_flicker.json's motions a faster fade (0.9) or a slower one (0.99) flickered more
// (docs/methods.md, "Still frames refined per pixel").
constexpr float kPixelFade = 0.97f;
// A moving frame leaves in each pixel its fetch (apply.comp's followFetch limits the next frame's
// detail by how far the fetch moved) instead of the weight the gathering carries: when the frames
// are still again, such a pixel's value carries this weight, about thirty still frames' gathering
// (the old weight, which a motion faded towards kPixelSeed, is gone by then). A weight of 1 moved
// the image two to three times as far at the first still frame, one of 16 took far longer to
// settle (docs/methods.md).
constexpr float kPixelResume = 4.0f;

// Whether, in a frame of the per-pixel history, the froxels take their centres, as the plain
// grid's, and the blend keeps none of the history: in a frame that starts the history (its grid is
// the one the still frames after it hold their pixels' detail against) and in one where a light
// changed and the camera did not. The pixels' detail, carried where the grid's change hides it,
// resolves what the jitter would, and the jitter's noise would only move the image: on
// bench/froxels_flicker.json's light motion the jittered, blended grid flickered more than the
// plain grid in 3 of 8 cases (the atrium's sun at Unreal's size 1.72x), the centres in none
// (docs/methods.md, "Still frames refined per pixel").
bool centredFroxels(const rg::PassContext& ctx, const FroxelPixelClock& clock,
                    const FrameConstants& now) {
    if (!clock.pixels.valid()) return false;
    if (!ctx.history(clock.pixels).valid) return true;
    const PreviousFrame& before = ctx.data(clock.previous);
    return before.lightsChanged && before.constants.viewProj == now.viewProj;
}

// The frame before's world -> clip, as a map from offsets to this frame's camera: composed in
// double, so that a camera far from the origin loses no precision to the translation.
glm::mat4 previousFromCamera(const glm::mat4& previousViewProj, const FrameConstants& now) {
    const glm::dmat4 t = glm::translate(glm::dmat4(1.0), glm::dvec3(glm::vec3(now.cameraPos)));
    return glm::mat4(glm::dmat4(previousViewProj) * t);
}

// The smallest Lin scale of the frame's lights: the integrated grid holds all of them.
float gridStorage(const rg::PassContext& ctx,
                  const std::vector<rg::HostDataRef<LightFrame>>& lights) {
    float s = 1.0f;
    for (const auto& l : lights) s = std::min(s, ctx.data(l).constants.linStorage.x);
    return s;
}

}  // namespace

// A point light's cube map (`cube`, with a shadow map) comes without light color, as cone-march's.
// `slab`: a point or spot light's table is bound, and each froxel takes its slice in closed form.
rg::ShaderCode froxelInjectShader(bool shadowMap, bool lightColor, bool cube, bool slab,
                                  bool noise) {
    return pickShader(ls_spirv::inject_comp_variants,
                      {{"LS_SHADOW_MAP", shadowMap},
                       {"LS_CUBE_SHADOW", shadowMap && cube},
                       {"LS_LIGHT_COLOR", lightColor && !(shadowMap && cube)},
                       {"LS_SLAB", slab},
                       {"LS_FROXEL_NOISE", noise}});
}

rg::ShaderCode froxelIntegrateShader(bool samples) {
    return pickShader(ls_spirv::integrate_comp_variants, {{"LS_FROXEL_PIXEL_HISTORY", samples}});
}

rg::ShaderCode froxelApplyShader(const CompositeVariant& target, bool pixels) {
    return pickCompositeShader(ls_spirv::apply_comp_variants, {{"LS_FROXEL_PIXEL_HISTORY", pixels}},
                               target);
}

glm::vec3 froxelJitterStep(uint32_t index) {
    // 1 / g^k for g the plastic number's three-dimensional kin, x = x^4 - 1's real root above 1.
    constexpr double g = 1.2207440846057594754;
    const glm::dvec3 a(1.0 / g, 1.0 / (g * g), 1.0 / (g * g * g));
    return glm::vec3(glm::fract(a * double(index)));
}

glm::vec2 froxelGridShift(uint32_t index) {
    // 1 / g^k for g the plastic number, x = x^3 - 1's real root above 1.
    constexpr double g = 1.3247179572447460260;
    const glm::dvec2 a(1.0 / g, 1.0 / (g * g));
    return glm::vec2(glm::fract(0.5 + a * double(index)) - 0.5);
}

FroxelColumns froxelColumns(const rg::PassContext& ctx, const FroxelPixelClock& clock,
                            const FrameConstants& now) {
    if (!clock.pixels.valid()) return {};
    const rg::HistoryState h = ctx.history(clock.pixels);
    const PreviousFrame& before = ctx.data(clock.previous);
    FroxelColumns c;
    // The frame before had a history of its own (it was the second of them at least) and had not
    // moved from the one before it.
    c.stillBefore = h.valid && h.age >= 2 && !before.beforeMoved;
    if (!h.valid || before.lightsChanged || before.constants.viewProj != now.viewProj) return c;
    c.still = true;
    c.shift = froxelGridShift(h.age);
    return c;
}

rg::PersistentImageDesc froxelPixelHistoryDesc(VkExtent2D screen) {
    rg::PersistentImageDesc d;
    d.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    d.extent = screen;
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    // The apply reads one and writes the other, each frame in the other role.
    d.stages = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    d.waitAccess = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    d.handAccess = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
    return d;
}

rg::PersistentImageDesc froxelHistoryDesc(const FroxelGrid& grid) {
    rg::PersistentImageDesc d;
    d.format = kFroxelScatteringFormat;
    d.extent = {grid.columns, grid.rows};
    d.depth = grid.slices;
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    // Compute passes read and write the two images, each frame in the other role: a frame waits
    // for the frame before's writes (to read them) and reads (to overwrite them).
    d.stages = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    d.waitAccess = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    d.handAccess = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
    return d;
}

FroxelSettings froxelSettings(const lightscatter::FroxelsSettings& s) {
    return {s.tile, s.slices, s.farDistance, s.temporal, s.historyWeight, s.pixelHistory};
}

FroxelGrid froxelGrid(VkExtent2D screen, const FroxelSettings& s) {
    FroxelGrid g;
    g.tile = std::max(s.tile, 1u);
    g.columns = (screen.width + g.tile - 1) / g.tile;
    g.rows = (screen.height + g.tile - 1) / g.tile;
    g.slices = s.slices;
    g.farDistance = s.farDistance;
    return g;
}

FroxelDepthRange froxelDepthRange(float nearPlane, float farPlane, bool infiniteFar,
                                  float maxDistance, float farDistance) {
    float farZ = maxDistance;
    if (farDistance > 0.0f) farZ = std::min(farZ, farDistance);
    if (!infiniteFar) farZ = std::min(farZ, farPlane);
    return {nearPlane, std::max(farZ, nearPlane * 1.001f)};
}

rg::ImageRef froxelScatteringImage(rg::RenderGraph& graph, const FroxelGrid& grid) {
    return graph.createImage(
        "froxel in-scattering",
        rg::ImageDesc::volume(kFroxelScatteringFormat, grid.columns, grid.rows, grid.slices));
}

rg::ImageRef addFroxelInjection(rg::RenderGraph& graph, const FroxelInjectInputs& in,
                                const FroxelGrid& grid) {
    const bool first = in.first;
    auto pass = graph.addPass("froxel light injection", rg::PassType::Compute);
    const auto& s = samplersOf(in.chain.shared);
    rg::BindingTable table = frameTable(pass, in.chain.constants);
    table
        .sampledIfValid(LS_BINDING_SHADOW_MAP, in.light.shadowMap, s.nearest(),
                        VK_IMAGE_ASPECT_DEPTH_BIT)
        .sampledIfValid(LS_BINDING_LIGHT_COLOR, in.light.lightColor, s.linear())
        .sampledIfValid(LS_BINDING_POINT_TABLE, in.light.table, s.nearest());
    if (in.noise.valid()) table.storageRead(LS_BINDING_FROXEL_NOISE, in.noise);
    const rg::ImageRef scattering =
        first ? table.storageWrite(LS_BINDING_FROXEL_SCATTERING, in.scattering)
              : table.storageReadWrite(LS_BINDING_FROXEL_SCATTERING, in.scattering);
    const bool shadow = in.light.shadowMap.valid(), color = in.light.lightColor.valid();
    const bool slab = in.light.table.valid(), noise = in.noise.valid();
    pass.execute([frame = in.chain, table, grid, first, shadow, color, slab, noise,
                  history = in.history, clock = in.clock](rg::PassContext& ctx) {
        const LightFrame& values = ctx.data(frame.values);
        FroxelPush push = froxelPush(values.constants, grid, 1.0f);
        const bool still = stepColumns(push, ctx, clock, values.constants).still;
        const rg::ImageRef steps = clock.pixels.valid() ? clock.pixels : history;
        if (noise) push.jitter = glm::vec4(froxelJitterStep(ctx.history(steps).age), kJitterSpread);
        if (centredFroxels(ctx, clock, values.constants)) push.jitter.w = 0.0f;
        // The columns the light's volume may reach (its screen rectangle, in froxels; one more on
        // each side when the columns are offset).
        const VkRect2D r = values.screenRect;
        const uint32_t pad = still ? 1 : 0;
        const uint32_t x0 =
            uint32_t(r.offset.x) / grid.tile - std::min(pad, uint32_t(r.offset.x) / grid.tile);
        const uint32_t y0 =
            uint32_t(r.offset.y) / grid.tile - std::min(pad, uint32_t(r.offset.y) / grid.tile);
        const uint32_t x1 =
            std::min(grid.columns,
                     (uint32_t(r.offset.x) + r.extent.width + grid.tile - 1) / grid.tile + pad);
        const uint32_t y1 = std::min(
            grid.rows, (uint32_t(r.offset.y) + r.extent.height + grid.tile - 1) / grid.tile + pad);
        push.columns = {float(x0), float(y0), float(std::max(x0, x1)), float(std::max(y0, y1))};
        if (!first && (x1 <= x0 || y1 <= y0)) return;  // a later light that reaches no column
        rg::Specialization spec = frame.spec.constants();
        spec.set(LS_SPEC_FROXEL_FIRST_LIGHT, first);
        const auto& p = frame.shared->pipelines.compute(
            "froxel light injection",
            froxelInjectShader(shadow, color, frame.spec.cubeShadow, slab, noise), table.layout(),
            sizeof(FroxelPush), spec);
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        p.push(ctx.cmd(), push);
        const uint32_t w = first ? grid.columns : x1 - x0, h = first ? grid.rows : y1 - y0;
        // The closed form marches each column in one invocation (8 x 8 columns a group); the
        // point samples take a froxel each (32 x 4 of one slice, as the temporal blend).
        if (slab)
            ctx.vk().CmdDispatch(ctx.cmd(), groupCount(w, 8), groupCount(h, 8), 1);
        else
            dispatchPerFroxel(ctx, w, h, grid.slices);
    });
    return scattering;
}

rg::ImageRef addFroxelTemporalBlend(rg::RenderGraph& graph, const FroxelTemporalInputs& in,
                                    const FroxelGrid& grid) {
    auto pass = graph.addPass("froxel temporal blend", rg::PassType::Compute);
    rg::BindingTable table = frameTable(pass, in.chain.constants);
    table.storageRead(LS_BINDING_FROXEL_SCATTERING, in.scattering);
    table.storageRead(LS_BINDING_FROXEL_HISTORY, in.history);
    const rg::ImageRef blended = table.storageWrite(LS_BINDING_FROXEL_HISTORY_OUT, in.historyOut);
    pass.execute([frame = in.chain, previous = in.previous, history = in.history,
                  weight = in.weight, table, grid, clock = in.clock](rg::PassContext& ctx) {
        const PreviousFrame& before = ctx.data(previous);
        const FrameConstants& constants = ctx.data(frame.values).constants;
        const rg::HistoryState kept = ctx.history(history);
        const bool valid = kept.valid && before.lightJump <= kLightJump;
        // The per-pixel history's still frames sample offset columns: the grid stays as it was,
        // copied into the image the next frame reads. From the second such frame on, that image
        // already holds it (the first copied it into the other, which the frame before read from),
        // and nothing is written.
        const FroxelColumns columns = froxelColumns(ctx, clock, constants);
        const bool keep = valid && columns.still;
        if (keep && columns.stillBefore && kept.age >= 2) return;
        const FroxelPush now = froxelPush(constants, grid, 1.0f);
        const FroxelPush then = froxelPush(before.constants, grid, 1.0f);
        FroxelTemporalPush push{};
        push.grid = now.grid;
        push.slices = now.slices;
        push.previousViewProj = before.constants.viewProj;
        push.previousSlices = glm::vec4(glm::vec3(then.slices), valid ? 1.0f : 0.0f);
        const bool cameraMoved = before.constants.viewProj != constants.viewProj;
        const float w = centredFroxels(ctx, clock, constants) ? 0.0f : weight;
        push.blend = {cameraMoved ? movingCameraWeight(w) : w, before.lightsChanged ? 1.0f : 0.0f,
                      kDropOutside, keep ? 1.0f : 0.0f};
        const auto& p = frame.shared->pipelines.compute(
            "froxel temporal blend", rg::spirv(ls_spirv::temporal_comp), table.layout(),
            sizeof(FroxelTemporalPush), {});
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        p.push(ctx.cmd(), push);
        dispatchPerFroxel(ctx, grid.columns, grid.rows, grid.slices);
    });
    return blended;
}

rg::ImageRef addFroxelIntegration(rg::RenderGraph& graph, const FroxelIntegrateInputs& in,
                                  const FroxelGrid& grid) {
    const char* name = in.volume ? "froxel volume integration" : "froxel integration";
    auto pass = graph.addPass(name, rg::PassType::Compute);
    rg::BindingTable table = frameTable(pass, in.chain.constants);
    table.storageRead(LS_BINDING_FROXEL_SCATTERING, in.scattering);
    const bool samples = in.samples.valid();
    if (samples) table.storageRead(LS_BINDING_FROXEL_SAMPLES, in.samples);
    const rg::ImageRef integrated = table.storageWrite(
        LS_BINDING_FROXEL_INTEGRATED,
        graph.createImage(
            in.volume ? "froxel volume's integrated in-scattering"
                      : "froxel integrated in-scattering",
            rg::ImageDesc::volume(kFroxelIntegratedFormat, grid.columns, grid.rows, grid.slices)));
    pass.execute([frame = in.chain, lights = in.lights, table, grid, name, samples,
                  clock = in.clock, onlyStill = in.onlyStill](rg::PassContext& ctx) {
        const FrameConstants& constants = ctx.data(frame.values).constants;
        if (onlyStill.pixels.valid() && !froxelColumns(ctx, onlyStill, constants).still) return;
        FroxelPush push = froxelPush(constants, grid, gridStorage(ctx, lights));
        stepColumns(push, ctx, clock, constants);
        const auto& p =
            frame.shared->pipelines.compute(name, froxelIntegrateShader(samples), table.layout(),
                                            sizeof(FroxelPush), frame.spec.constants());
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        p.push(ctx.cmd(), push);
        ctx.vk().CmdDispatch(ctx.cmd(), groupCount(grid.columns, 8), groupCount(grid.rows, 8), 1);
    });
    return integrated;
}

CompositeOutputs addFroxelApply(rg::RenderGraph& graph, const FroxelApplyInputs& in,
                                const FroxelGrid& grid) {
    auto pass = graph.addPass("froxel apply", rg::PassType::Compute);
    const auto& s = samplersOf(in.chain.shared);
    rg::BindingTable table = frameTable(pass, in.chain.constants);
    table.sampled(LS_BINDING_DEPTH, in.chain.depth, s.nearest(), VK_IMAGE_ASPECT_DEPTH_BIT)
        .sampled(LS_BINDING_FROXEL_INTEGRATED, in.integrated, s.linear());
    const bool pixels = in.clock.pixels.valid();
    if (pixels) {
        table.storageRead(LS_BINDING_FROXEL_PIXELS, in.clock.pixels);
        table.sampled(LS_BINDING_FROXEL_KEPT, in.kept, s.linear());
        graph.markOutput(table.storageWrite(LS_BINDING_FROXEL_PIXELS_OUT, in.pixelsOut));
    }
    const CompositeOutputs written = addCompositeTarget(table, in.target);
    pass.execute([frame = in.chain, lights = in.lights, table, grid, written, pixels,
                  clock = in.clock](rg::PassContext& ctx) {
        const FrameConstants& c = ctx.data(frame.values).constants;
        FroxelPush now = froxelPush(c, grid, gridStorage(ctx, lights));
        FroxelApplyPush push{};
        if (pixels) {
            if (stepColumns(now, ctx, clock, c).still) {
                push.history = {kPixelWidth, kPixelWeight, 1.0f, kPixelResume};
            } else {
                // A frame that moved carries each pixel's detail from where the frame before saw
                // its surface, unless the history is gone (a camera cut, a light's jump, a new
                // frame size): then each pixel starts again from its trilinear fetch.
                const PreviousFrame& before = ctx.data(clock.previous);
                const bool carried = ctx.history(clock.pixels).valid &&
                                     before.lightJump <= kLightJump &&
                                     before.constants.screenSize == c.screenSize;
                const bool cameraMoved = before.constants.viewProj != c.viewProj;
                push.history = {cameraMoved ? kPixelWidth : 0.0f, carried ? kPixelFade : 0.0f, 0.0f,
                                kPixelSeed};
                push.previousFromCamera = previousFromCamera(before.constants.viewProj, c);
            }
        }
        push.grid = now.grid;
        push.slices = now.slices;
        push.shift = now.shift;
        const rg::ShaderCode shader = froxelApplyShader(compositeVariant(ctx, written), pixels);
        const auto& p = frame.shared->pipelines.compute("froxel apply", shader, table.layout(),
                                                        sizeof(FroxelApplyPush), {});
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        p.push(ctx.cmd(), push);
        const VkExtent2D e = ctx.extent(written.color);
        ctx.vk().CmdDispatch(ctx.cmd(), groupCount(e.width, 8), groupCount(e.height, 8), 1);
    });
    return written;
}

rg::ImageRef addFroxelExport(rg::RenderGraph& graph, const FroxelExportInputs& in,
                             const FroxelGrid& grid) {
    auto pass = graph.addPass("froxel volume export", rg::PassType::Compute);
    rg::BindingTable table = frameTable(pass, in.chain.constants);
    table.storageRead(LS_BINDING_FROXEL_INTEGRATED, in.integrated);
    const rg::ImageRef written = table.storageWrite(LS_BINDING_FROXEL_VOLUME_OUT, in.volumeOut);
    pass.execute([frame = in.chain, lights = in.lights, table, grid](rg::PassContext& ctx) {
        const FrameConstants& constants = ctx.data(frame.values).constants;
        const FroxelPush push = froxelPush(constants, grid, gridStorage(ctx, lights));
        const auto& p = frame.shared->pipelines.compute("froxel volume export",
                                                        rg::spirv(ls_spirv::export_comp),
                                                        table.layout(), sizeof(FroxelPush), {});
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        p.push(ctx.cmd(), push);
        dispatchPerFroxel(ctx, grid.columns, grid.rows, grid.slices);
    });
    return written;
}

}  // namespace ls
