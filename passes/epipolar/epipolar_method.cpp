#include "epipolar_method.h"

#include "epipolar_constants.h"
#include "epipolar_nodes.h"
#include "lightscatter/lightscatter.h"
#include "min_max_trees.h"
#include "screen_share.h"
#include "shared/chain_inputs.h"
#include "shared/refusals.h"
#include "shared/scattering_params.h"
#include "shared/shared_nodes.h"
#include "shared/view_reach.h"
#include "step_counts.h"

namespace ls {

namespace {

lightscatter::EpipolarSettings sized(lightscatter::EpipolarSettings s, const LineSizes& sizes) {
    s.slices = sizes.slices;
    s.samplesPerSlice = sizes.samples;
    return s;
}

}  // namespace

const MethodUnit& methodUnitEpipolar() {
    static const EpipolarMethod unit;
    return unit;
}

std::string EpipolarMethod::description() const {
    return "seed 000's epipolar sampling with 1D min/max trees (the main method)";
}

MethodCaps EpipolarMethod::caps() const {
    MethodCaps c;
    c.cubeShadow = true;
    c.countsSteps = true;
    c.profileSized = true;
    // Lit runs integrate the medium (integrate.glsl) between the trees' skips; Lin is
    // interpolated and refined on its differences (epipolar_constants.h).
    c.media = true;
    return c;
}

// Seed 000, "Performance": 2560x1600 on a GeForce GTX 680 for the three main profiles, 1366x768
// (the Quadro 1000M) for the weaker-device set (the Intel HD table at 1024x768 repeats the same
// memory figures).
std::optional<lightscatter::SeedFigure> EpipolarMethod::seedFigure(lightscatter::Profile p) const {
    using lightscatter::Profile;
    switch (p) {
        case Profile::HighQuality:
            return lightscatter::SeedFigure{2560, 1600, 88.0, 5.986};
        case Profile::Balanced:
            return lightscatter::SeedFigure{2560, 1600, 44.0, 3.269};
        case Profile::HighPerformance:
            return lightscatter::SeedFigure{2560, 1600, 18.0, 2.267};
        case Profile::LowHighQuality:
            return lightscatter::SeedFigure{1366, 768, 44.0, 18.9};
        case Profile::LowBalanced:
            return lightscatter::SeedFigure{1366, 768, 11.0, 8.37};
        case Profile::LowHighPerformance:
            return lightscatter::SeedFigure{1366, 768, 4.5, 5.38};
        default:
            return std::nullopt;
    }
}

uint64_t EpipolarMethod::stepCountBytes(const LightSetup& s) const {
    return ls::stepCountBytes(s.settings.epipolar.slices);
}

void EpipolarMethod::readStepCounts(const void* counters, uint64_t bytes,
                                    lightscatter::StepCounts& out) const {
    const auto rows = static_cast<uint32_t>(bytes / ls::stepCountBytes(1));
    const auto sum = sumStepCounts(static_cast<const uint32_t*>(counters), rows);
    auto at = [&](StepCount k) { return sum[static_cast<uint32_t>(k)]; };
    out.samples = at(StepCount::Samples);
    out.rays = at(StepCount::Rays);
    out.lineSteps = at(StepCount::LineSteps);
    out.treeNodes = at(StepCount::TreeNodes);
    out.degenerateRays = at(StepCount::DegenerateRays);
    out.degenerateSteps = at(StepCount::DegenerateSteps);
    out.listedSamples = at(StepCount::Listed);
    out.unbuiltTreeNodes = at(StepCount::UnbuiltTreeNodes);
}

bool EpipolarMethod::readsTable(const LightSetup& s) const {
    return pointLike(s);
}

std::unique_ptr<LightData> EpipolarMethod::makeData() const {
    return std::make_unique<EpipolarFrame>();
}

std::vector<CpuWork> EpipolarMethod::prepare(LightData* data, LightFrame& frame,
                                             const LightSetup& light) const {
    EpipolarFrame& e = *static_cast<EpipolarFrame*>(data);
    const LineSizes before = e.rectSizes;
    e.rectSizes = sizesForRect(light.settings.epipolar, light.screen, light.screenRect,
                               before.slices != 0 ? &before : nullptr);
    const glm::vec4 bounds = lineBounds(light.screen, light.screenRect);
    const LineWindow windowBefore = e.window;
    std::vector<glm::vec2> cone;
    if (light.light.kind == LightType::Spot && frame.constants.lightScreen.z > 0.0f) {
        if (auto corners = lightScreenCorners(light.camera, light.light, light.medium, true))
            cone = std::move(*corners);
    }
    e.window = lineWindow(cone, glm::vec2(frame.constants.lightScreen), bounds, e.rectSizes.slices,
                          windowBefore.border != 0 ? &windowBefore : nullptr);
    e.sizes = {e.window.slices, e.rectSizes.samples};
    e.full = {light.settings.epipolar.slices, light.settings.epipolar.samplesPerSlice};
    e.rect = light.screenRect;
    e.constants =
        makeEpipolarConstants(sized(light.settings.epipolar, e.sizes), light.light.shadowMapSize,
                              interpolatesLin(light), refinesByDefault(light), bounds);
    e.constants.window = {static_cast<float>(e.window.first), static_cast<float>(e.window.border),
                          e.window.part() ? static_cast<float>(e.window.needed) : 0.0f,
                          static_cast<float>(e.window.neededFrom)};
    if (!cubeShadowed(light)) return {};
    for (int face = 0; face < 6; ++face)
        e.faceInView[face] = cubeFaceTouchesView(light.camera, light.light, light.medium, face);
    e.constants.cubeFaces.x = static_cast<float>(e.facesInView());
    return {};
}

ChainOptions EpipolarMethod::options(const LightSetup& s, const LightData* data,
                                     const ChainOptions*) const {
    // The light's own sizes (prepare()'s); the settings' where there is no frame (the budget).
    const lightscatter::EpipolarSettings e =
        data != nullptr ? sized(s.settings.epipolar, static_cast<const EpipolarFrame*>(data)->sizes)
                        : s.settings.epipolar;
    Options o;
    o.slices = e.slices;
    o.samples = e.samplesPerSlice;
    o.marchPhases = marchPhases(e);
    o.minMaxTrees = e.minMaxTrees && treesFit(s.light.shadowMapSize);
    o.fixup = e.fixup;
    o.inscatterRefinement = inscatterRefinementOf(e, refinesByDefault(s)) > 0.0f;
    o.marchList = marchesFromList(e, o.inscatterRefinement);
    return ChainOptions(o);
}

ChainOutputs EpipolarMethod::addChain(rg::RenderGraph& g, ChainLights lights,
                                      const CompositeTarget& target) const {
    const ChainLight& only = onlyLight(lights, name());
    const ChainInputs& in = only.in;
    const ChainConfig& c = only.config;
    const ChainContext chain = chainContext(in, c);
    const LightImages light = lightImages(in, c);
    ChainOutputs out;
    if (!c.shadowed) {
        out.lin = addUnshadowed(g, {chain, light});
        return out;
    }
    const Options& o = *c.options.get<Options>();
    const EpipolarOptions options{.sizes = {o.slices, o.samples, o.marchPhases, o.marchList},
                                  .minMaxTrees = o.minMaxTrees,
                                  .fixup = o.fixup,
                                  .cubeShadow = c.light == LightType::Point,
                                  .inscatterRefinement = o.inscatterRefinement};
    // Composited in the chain's unwarp and fix-up: no composite pass.
    const EpipolarOutputs e = addEpipolarNodes(g, {chain, light, target, in.stepCounts}, options);
    out.composited = true;
    out.target = e.composited;
    out.stepCounts = e.stepCounts;
    return out;
}

std::string EpipolarMethod::summary(const ChainConfig& c) const {
    if (!c.shadowed) return unshadowedSummary(c);
    const Options& o = *c.options.get<Options>();
    return std::string("epipolar sampling") + (o.minMaxTrees ? " with min/max trees" : "") +
           (c.light == LightType::Point ? " on every cube face" : "") +
           (o.inscatterRefinement ? ", refined on in-scattering differences" : "") +
           (o.fixup ? ", fix-up" : "") + ", composited in the unwarp";
}

std::string EpipolarMethod::frameNote(const LightFrame& frame, const ChainConfig& c) const {
    if (!frame.data || !c.shadowed) return {};
    const EpipolarFrame& e = epipolarFrameOf(frame);
    std::string lines;
    if (e.rectSizes != e.full)
        lines = "lines within its " + std::to_string(e.rect.extent.width) + "x" +
                std::to_string(e.rect.extent.height) +
                " screen rectangle: " + std::to_string(e.rectSizes.slices) + " slices of " +
                std::to_string(e.rectSizes.samples) + " samples";
    if (e.window.part())
        lines += std::string(lines.empty() ? "lines" : ", and") +
                 " within its wedge of the screen: " + std::to_string(e.window.slices) +
                 " of the border's " + std::to_string(e.window.border) + " slices, from slice " +
                 std::to_string(e.window.first);
    if (c.light != LightType::Point) return lines;
    std::string list;
    for (int f = 0; f < 6; ++f)
        if (e.inView(f)) list += std::string(list.empty() ? "" : ", ") + cubeFaceName(f);
    return (lines.empty() ? "" : lines + "; ") +
           "cube faces reaching the view: " + (list.empty() ? std::string("none") : list) +
           " (the others are skipped)";
}

}  // namespace ls
