#include "beam_tree_methods.h"

#include <algorithm>

#include "beam_tree_nodes.h"
#include "shared/chain_inputs.h"
#include "shared/refusals.h"

namespace ls {
namespace {

// The triangle buffer's first size, in points.
constexpr uint32_t kFirstCapacity = 3 * 4096;

}  // namespace

const MethodUnit& methodUnitBeamTreeAnalytic() {
    static const BeamTreeAnalyticMethod unit;
    return unit;
}

const MethodUnit& methodUnitBeamTreeSampling() {
    static const BeamTreeSamplingMethod unit;
    return unit;
}

MethodCaps BeamTreeMethod::caps() const {
    MethodCaps c;
    c.directional = false;  // the beam tree is built from a point
    c.readsOccluders = true;
    c.cubeShadow = true;  // the sampling planes look up the face each point lies in
    c.profileSized = true;
    return c;
}

// The lit pyramids integrate the light in closed form, shadowed or not: a color that varies along
// the ray cannot enter them (beam-tree-sampling's planes look the color up), and seed 004's
// simplified model is their other closed form.
MethodCaps BeamTreeAnalyticMethod::caps() const {
    MethodCaps c = BeamTreeMethod::caps();
    c.lightColor = c.unshadowedLightColor = false;
    c.simplifiedModel = true;
    return c;
}

// Every point is a plane's sample (planes.frag), which weighs its density and optical depth; the
// analytic variant's lit pyramids are closed forms of a homogeneous medium, and refuse the others.
MethodCaps BeamTreeSamplingMethod::caps() const {
    MethodCaps c = BeamTreeMethod::caps();
    c.media = true;
    return c;
}

std::string BeamTreeAnalyticMethod::description() const {
    return "seed 004's beam tree: lit space in closed form, uncertain space sampled by planes";
}

std::string BeamTreeSamplingMethod::description() const {
    return "seed 004's beam tree clipping seed 002's planes, shadow look-ups in uncertain space";
}

std::string BeamTreeMethod::refusal(const LightSetup& s) const {
    return refuseNoDepthAttachment(
        s, "method " + std::string(name()) + " (seed 004) depth-tests its sampling planes");
}

std::string BeamTreeMethod::notice(const LightSetup& s) const {
    if (s.occluders != 0) return {};
    return std::string(name()) +
           " has no occluders (FrameDescription::occluders): it treats the whole light volume as "
           "lit, so " +
           (litSpace() == LitSpace::ClosedForm ? "nothing casts a shadow"
                                               : "it never looks the shadow map up");
}

std::string BeamTreeMethod::frameNote(const LightFrame& frame, const ChainConfig&) const {
    if (!frame.data) return {};
    const PlanePush& p = static_cast<const BeamTreeData*>(frame.data)->frame.planePush;
    return planesNote(static_cast<uint32_t>(p.boxMax.z), p.boxMin.w);
}

std::unique_ptr<LightData> BeamTreeMethod::makeData() const {
    return std::make_unique<BeamTreeData>();
}

std::vector<CpuWork> BeamTreeMethod::prepare(LightData* data, LightFrame&,
                                             const LightSetup& s) const {
    PlaneSettings planes;
    // Only the count or spacing: the other settings are the planes method's.
    planes.planes = s.settings.planes.count;
    planes.spacing = s.settings.planes.spacing;
    BeamTreeFrame& frame = static_cast<BeamTreeData*>(data)->frame;
    frame = buildBeamTreeFrame(s.camera, s.light, s.medium, s.beamOccluders, planes, litSpace());
    return {{"beam tree (CPU, seed 004)", frame.buildMilliseconds}};
}

ChainOptions BeamTreeMethod::options(const LightSetup& s, const LightData* data,
                                     const ChainOptions* previous) const {
    const Options* before = previous ? previous->get<Options>() : nullptr;
    Options o;
    o.reversedZ = s.camera.reversedZ;
    o.capacityPoints = before ? std::max(before->capacityPoints, kFirstCapacity) : kFirstCapacity;
    if (data)
        while (o.capacityPoints < static_cast<const BeamTreeData*>(data)->frame.points.size())
            o.capacityPoints *= 2;
    return ChainOptions(o);
}

ChainOutputs BeamTreeAnalyticMethod::addChain(rg::RenderGraph& g, ChainLights lights,
                                              const CompositeTarget&) const {
    const ChainLight& only = onlyLight(lights, name());
    const ChainInputs& in = only.in;
    const ChainConfig& c = only.config;
    const Options& o = *c.options.get<Options>();
    const BeamTreeInputs beam{chainContext(in, c), lightImages(in, c)};
    ChainOutputs out;
    out.lin = addBeamTreeHybrid(g, beam, {o.capacityPoints, o.reversedZ});
    return out;
}

std::string BeamTreeAnalyticMethod::summary(const ChainConfig& c) const {
    return std::string("seed 004's beam tree: lit pyramids in closed form") +
           (c.shadowed ? ", uncertain space sampled by planes with the shadow map"
                       : ", uncertain space sampled by planes as lit (no shadow map)");
}

ChainOutputs BeamTreeSamplingMethod::addChain(rg::RenderGraph& g, ChainLights lights,
                                              const CompositeTarget&) const {
    const ChainLight& only = onlyLight(lights, name());
    const ChainInputs& in = only.in;
    const ChainConfig& c = only.config;
    const Options& o = *c.options.get<Options>();
    const BeamTreeSamplingInputs beam{chainContext(in, c), lightImages(in, c)};
    ChainOutputs out;
    out.lin = addBeamTreeSampling(g, beam, {o.capacityPoints, o.reversedZ});
    return out;
}

std::string BeamTreeSamplingMethod::summary(const ChainConfig& c) const {
    return std::string(
               "seed 004's beam tree clipping seed 002's planes (near the light thinner, their "
               "slabs in closed form): lit parts without shadow look-ups") +
           (c.shadowed ? ", uncertain parts with the shadow map"
                       : ", uncertain parts as lit (no shadow map)");
}

}  // namespace ls
