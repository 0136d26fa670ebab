#include "analytic_method.h"

#include "analytic_node.h"
#include "shared/chain_inputs.h"
#include "shared/refusals.h"

namespace ls {

MethodCaps AnalyticMethod::caps() const {
    MethodCaps c;
    c.directional = false;
    return c;
}

std::string AnalyticMethod::refusal(const LightSetup& s) const {
    if (std::string r = refuseCubeShadow(s, name()); !r.empty()) return r;
    if (!pointLike(s))
        return "method analytic (seed 001) is a closed form for point and spot lights; this "
               "frame's "
               "light is directional (use auto, epipolar or cone-march)";
    if (s.shadowed)
        return "method analytic (seed 001) cannot cast shadows; this frame has a shadow map (use "
               "auto, epipolar, brute-force or cone-march)";
    return firstRefusal(
        {refuseNoise(s, name()),
         refuseUnshadowedLightColor(s, name(),
                                    "(seed 001) integrates an unshadowed light in closed form")});
}

std::string AnalyticMethod::notice(const LightSetup& s) const {
    // The simplified model is seed 001's form by definition: nothing to warn about.
    if (s.simplified) return {};
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

ChainOutputs AnalyticMethod::addChain(rg::RenderGraph& g, const ChainInputs& in,
                                      const ChainConfig& c, const CompositeTarget&) const {
    ChainOutputs out;
    out.lin = addAnalytic(g, {frameContext(in, c)});
    return out;
}

std::string AnalyticMethod::summary(const ChainConfig&) const {
    return "seed 001's arctangent closed form per pixel";
}

}  // namespace ls
