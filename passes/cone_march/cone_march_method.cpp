#include "cone_march_method.h"

#include "cone_march_node.h"
#include "shared/chain_inputs.h"
#include "shared/refusals.h"

namespace ls {

std::string ConeMarchMethod::refusal(const LightSetup& s) const {
    return firstRefusal({refuseNoise(s, name()), refuseSimplified(s, name())});
}

ChainOptions ConeMarchMethod::options(const LightSetup& s, const LightData*,
                                      const ChainOptions*) const {
    return ChainOptions(Options{s.cone, s.shadowSampling});
}

ChainOutputs ConeMarchMethod::addChain(rg::RenderGraph& g, const ChainInputs& in,
                                       const ChainConfig& c, const CompositeTarget&) const {
    const Options& o = *c.options.get<Options>();
    LightImages light;
    if (c.shadowed && o.shadowSampling) light.shadowMap = in.shadowMap;
    light.lightColor = in.lightColor;
    light.shadowMapSize = c.shadowMapSize;
    ChainOutputs out;
    out.lin = addConeMarch(g, {frameContext(in, c), light}, o.march);
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
