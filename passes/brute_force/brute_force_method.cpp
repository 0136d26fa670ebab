#include "brute_force_method.h"

#include "brute_force_node.h"
#include "shared/chain_inputs.h"
#include "shared/refusals.h"
#include "shared/shared_nodes.h"

namespace ls {

const MethodUnit& methodUnitBruteForce() {
    static const BruteForceMethod unit;
    return unit;
}

std::string BruteForceMethod::description() const {
    return "every pixel marches its ray through every shadow-map texel (the GPU reference)";
}

MethodCaps BruteForceMethod::caps() const {
    MethodCaps c;
    c.cubeShadow = true;
    c.media = true;  // integrate.glsl's non-uniform steps, per texel crossed
    return c;
}

bool BruteForceMethod::readsTable(const LightSetup& s) const {
    return pointLike(s);
}

ChainOptions BruteForceMethod::options(const LightSetup&, const LightData*,
                                       const ChainOptions*) const {
    return {};  // nothing but the light's kind, shadow and shadow-map size
}

ChainOutputs BruteForceMethod::addChain(rg::RenderGraph& g, ChainLights lights,
                                        const CompositeTarget&) const {
    const ChainLight& only = onlyLight(lights, name());
    const ChainInputs& in = only.in;
    const ChainConfig& c = only.config;
    const ChainContext chain = chainContext(in, c);
    const LightImages light = lightImages(in, c);
    ChainOutputs out;
    out.lin = c.shadowed ? addBruteForce(g, {chain, light}) : addUnshadowed(g, {chain, light});
    return out;
}

std::string BruteForceMethod::summary(const ChainConfig& c) const {
    return c.shadowed ? "brute-force ray marching" : unshadowedSummary(c);
}

}  // namespace ls
