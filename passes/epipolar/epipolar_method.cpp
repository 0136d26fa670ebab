#include "epipolar_method.h"

#include "epipolar_constants.h"
#include "epipolar_nodes.h"
#include "shared/chain_inputs.h"
#include "shared/refusals.h"
#include "shared/shared_nodes.h"
#include "shared/view_reach.h"

namespace ls {

MethodCaps EpipolarMethod::caps() const {
    MethodCaps c;
    c.cubeShadow = true;
    c.countsSteps = true;
    c.budgeted = true;
    return c;
}

std::string EpipolarMethod::refusal(const LightSetup& s) const {
    return firstRefusal(
        {refuseSkippedShadows(s, name()), refuseNoise(s, name()), refuseSimplified(s, name())});
}

bool EpipolarMethod::readsTable(const LightSetup& s) const {
    return pointLike(s);
}

std::unique_ptr<LightData> EpipolarMethod::makeData() const {
    return std::make_unique<EpipolarFrame>();
}

std::vector<CpuWork> EpipolarMethod::prepare(LightData* data, LightFrame&,
                                             const LightSetup& light) const {
    EpipolarFrame& e = *static_cast<EpipolarFrame*>(data);
    e.constants = makeEpipolarConstants(light.epipolar, light.light.shadowMapSize);
    if (!cubeShadowed(light)) return {};
    for (int face = 0; face < 6; ++face)
        e.faceInView[face] = cubeFaceTouchesView(light.camera, light.light, light.medium, face);
    return {};
}

ChainOptions EpipolarMethod::options(const LightSetup& s, const LightData*,
                                     const ChainOptions*) const {
    Options o;
    o.slices = s.epipolar.slices;
    o.samples = s.epipolar.samples;
    o.minMaxTrees = s.epipolar.minMaxTrees;
    o.fixup = s.epipolar.fixup;
    o.inscatterRefinement = s.epipolar.inscatterRefinementThreshold > 0.0f;
    return ChainOptions(o);
}

ChainOutputs EpipolarMethod::addChain(rg::RenderGraph& g, const ChainInputs& in,
                                      const ChainConfig& c, const CompositeTarget& target) const {
    const FrameContext frame = frameContext(in, c);
    const LightImages light = lightImages(in, c);
    ChainOutputs out;
    if (!c.shadowed) {
        out.lin = addUnshadowed(g, {frame, light});
        return out;
    }
    const Options& o = *c.options.get<Options>();
    const EpipolarOptions options{.sizes = {o.slices, o.samples},
                                  .minMaxTrees = o.minMaxTrees,
                                  .fixup = o.fixup,
                                  .cubeShadow = c.light == LightType::Point,
                                  .inscatterRefinement = o.inscatterRefinement};
    // Composited in the chain's unwarp and fix-up: no composite pass.
    const EpipolarOutputs e = addEpipolarNodes(g, {frame, light, target, in.stepCounts}, options);
    out.composited = true;
    out.target = e.composited;
    out.stepCounts = e.stepCounts;
    return out;
}

std::string EpipolarMethod::summary(const ChainConfig& c) const {
    if (!c.shadowed) return unshadowedSummary(c);
    const Options& o = *c.options.get<Options>();
    return std::string("epipolar sampling") + (o.minMaxTrees ? " with min/max trees" : "") +
           (c.light == LightType::Point ? " per cube face" : "") +
           (o.inscatterRefinement ? ", refined on in-scattering differences" : "") +
           (o.fixup ? ", fix-up" : "") + ", composited in the unwarp";
}

std::string EpipolarMethod::frameNote(const LightFrame& frame, const ChainConfig& c) const {
    if (!frame.data || !c.shadowed || c.light != LightType::Point) return {};
    const EpipolarFrame& e = epipolarFrameOf(frame);
    std::string list;
    for (int f = 0; f < 6; ++f)
        if (e.inView(f)) list += std::string(list.empty() ? "" : ", ") + cubeFaceName(f);
    return "cube faces reaching the view: " + (list.empty() ? std::string("none") : list) +
           " (the others' passes record no work)";
}

}  // namespace ls
