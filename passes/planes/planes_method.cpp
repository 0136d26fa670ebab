#include "planes_method.h"

#include "plane_nodes.h"
#include "shared/chain_inputs.h"
#include "shared/refusals.h"

namespace ls {

const MethodUnit& methodUnitPlanes() {
    static const PlanesMethod unit;
    return unit;
}

std::string PlanesMethod::description() const {
    return "seed 002's view-aligned planes blended across the light's volume";
}

MethodCaps PlanesMethod::caps() const {
    MethodCaps c;
    c.cubeShadow = true;  // each plane's point looks up the face it lies in
    c.profileSized = true;
    c.noise = true;
    c.skipsShadowSampling = true;
    c.media = true;  // each plane's point weighs its density and optical depth (planes.frag)
    return c;
}

std::string PlanesMethod::refusal(const LightSetup& s) const {
    return refuseNoDepthAttachment(s, "method planes (seed 002) depth-tests its planes");
}

std::unique_ptr<LightData> PlanesMethod::makeData() const {
    return std::make_unique<PlaneData>();
}

std::vector<CpuWork> PlanesMethod::prepare(LightData* data, LightFrame&,
                                           const LightSetup& s) const {
    static_cast<PlaneData*>(data)->placement =
        placePlanes(s.camera, s.light, s.medium, planeSettings(s.settings), s.timeSeconds);
    return {};
}

ChainOptions PlanesMethod::options(const LightSetup& s, const LightData*,
                                   const ChainOptions*) const {
    const lightscatter::PlanesSettings& p = s.settings.planes;
    return ChainOptions(Options{p.target, p.blur, p.dither, noisy(s), s.settings.shadowSampling,
                                s.camera.reversedZ});
}

ChainOutputs PlanesMethod::addChain(rg::RenderGraph& g, ChainLights lights,
                                    const CompositeTarget&) const {
    const ChainLight& only = onlyLight(lights, name());
    const ChainInputs& in = only.in;
    const ChainConfig& c = only.config;
    const Options& o = *c.options.get<Options>();
    const ChainContext chain = chainContext(in, c);
    PlanesInputs planes{chain, {}, {}};
    if (c.shadowed && o.shadowSampling) planes.light.shadowMap = in.shadowMap;
    planes.light.lightColor = in.lightColor;  // projected like the shadow map, with one or not
    planes.light.shadowMapSize = c.shadowMapSize;
    if (o.noise) planes.noise = in.noise;
    PlanesOptions planeOptions;
    planeOptions.target = o.target;
    planeOptions.dither = o.dither;
    planeOptions.reversedZ = o.reversedZ;
    const rg::ImageRef sum = addPlanes(g, planes, planeOptions);
    const PlaneResolveOptions resolve{o.target, o.blur, c.light == LightType::Directional};
    ChainOutputs out;
    out.lin = planeResolveNeeded(resolve) ? addPlaneResolve(g, {chain, sum}, resolve) : sum;
    return out;
}

std::string PlanesMethod::frameNote(const LightFrame& frame, const ChainConfig&) const {
    if (!frame.data) return {};
    const PlanePlacement& p = placementOf(frame);
    return planesNote(p.planes, p.push.boxMin.w);
}

std::string PlanesMethod::summary(const ChainConfig& c) const {
    const Options& o = *c.options.get<Options>();
    return std::string("seed 002's view-aligned planes") +
           (o.target == PlaneTarget::Rgba8Channels ? " into 8-bit channels"
            : o.target == PlaneTarget::Float32     ? " into a float32 target"
                                                   : "") +
           (c.shadowed && !o.shadowSampling ? ", no shadow-map sampling" : "") +
           (o.noise ? ", scrolling noise" : "") + (o.blur ? ", blurred" : "");
}

}  // namespace ls
