#include "analytic_method.h"

#include "analytic_node.h"
#include "shared/chain_inputs.h"
#include "shared/refusals.h"

namespace ls {

const MethodUnit& methodUnitAnalytic() {
    static const AnalyticMethod unit;
    return unit;
}

std::string AnalyticMethod::description() const {
    return "seed 001's arctangent closed form per pixel (unshadowed point and spot lights)";
}

MethodCaps AnalyticMethod::caps() const {
    MethodCaps c;
    c.directional = false;
    c.shadowMap = false;
    // One closed form over the whole ray cannot vary a light color along it (and without a shadow
    // map it never has one with a shadow map).
    c.lightColor = c.unshadowedLightColor = false;
    c.simplifiedModel = true;  // seed 004's model is seed 001's form
    return c;
}

std::string AnalyticMethod::notice(const LightSetup& s) const {
    // The simplified model is seed 001's form by definition: nothing to warn about.
    if (simplifiedModel(s)) return {};
    std::string notice;
    if (!isotropicMedium(s))
        notice = "analytic assumes isotropic scattering, but the medium has " +
                 std::string(glm::any(glm::greaterThan(s.medium.betaR, glm::vec3(0.0f)))
                                 ? "Rayleigh scattering"
                                 : "a Mie lobe") +
                 " (its phase function is replaced by 1/(4 pi))";
    // Its image error grows like 1.33 tau (tests/float64_model: AnalyticExtinction).
    const float tau = opticalDepthToLight(s);
    const float error = 1.33f * tau;
    if (error > 0.01f)
        notice += std::string(notice.empty() ? "analytic ignores extinction"
                                             : "; it also ignores extinction") +
                  ": optical depth " + twoDigits(tau) + " to the light, about " +
                  twoDigits(100.0f * error) + "% too bright";
    return notice;
}

ChainOptions AnalyticMethod::options(const LightSetup&, const LightData*,
                                     const ChainOptions*) const {
    return {};
}

ChainOutputs AnalyticMethod::addChain(rg::RenderGraph& g, ChainLights lights,
                                      const CompositeTarget&) const {
    const ChainLight& only = onlyLight(lights, name());
    const ChainInputs& in = only.in;
    const ChainConfig& c = only.config;
    ChainOutputs out;
    out.lin = addAnalytic(g, {chainContext(in, c)});
    return out;
}

std::string AnalyticMethod::summary(const ChainConfig&) const {
    return "seed 001's arctangent closed form per pixel";
}

}  // namespace ls
