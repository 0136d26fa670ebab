#include "cone_march_method.h"

#include "cone_march_node.h"
#include "shared/chain_inputs.h"

namespace ls {

const MethodUnit& methodUnitConeMarch() {
    static const ConeMarchMethod unit;
    return unit;
}

std::string ConeMarchMethod::description() const {
    return "seed 003's march of a fixed number of samples per pixel within the light's cone";
}

MethodCaps ConeMarchMethod::caps() const {
    MethodCaps c;
    c.cubeShadow = true;           // each sample looks up the face it lies in
    c.skipsShadowSampling = true;  // the seed's low-end mode
    c.media = true;                // per sample (cone_march.frag)
    return c;
}

ChainOptions ConeMarchMethod::options(const LightSetup& s, const LightData*,
                                      const ChainOptions*) const {
    const lightscatter::ConeMarchSettings& c = s.settings.coneMarch;
    return ChainOptions(Options{{c.samples, c.limited, c.jitter}, s.settings.shadowSampling});
}

ChainOutputs ConeMarchMethod::addChain(rg::RenderGraph& g, ChainLights lights,
                                       const CompositeTarget&) const {
    const ChainLight& only = onlyLight(lights, name());
    const ChainInputs& in = only.in;
    const ChainConfig& c = only.config;
    const Options& o = *c.options.get<Options>();
    LightImages light;
    if (c.shadowed && o.shadowSampling) light.shadowMap = in.shadowMap;
    light.lightColor = in.lightColor;
    light.shadowMapSize = c.shadowMapSize;
    ChainOutputs out;
    out.lin = addConeMarch(g, {chainContext(in, c), light}, o.march);
    return out;
}

std::string ConeMarchMethod::summary(const ChainConfig& c) const {
    const Options& o = *c.options.get<Options>();
    return std::string(o.march.coneLimited ? "cone-limited" : "naive full-ray") + " march, " +
           std::to_string(o.march.samples) + " samples per pixel" +
           (c.shadowed && !o.shadowSampling ? ", no shadow-map sampling" : "") +
           (o.march.jitter ? ", jittered" : "");
}

}  // namespace ls
