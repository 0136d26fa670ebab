#pragma once
// Seed 001's closed form as a method of the frame graph (method_unit.h): Lin of an unshadowed point
// or spot light per pixel, for an isotropic medium without extinction (its notice says what a
// frame that breaks that costs).
#include "shared/method_unit.h"

namespace ls {

class AnalyticMethod final : public MethodUnit {
  public:
    const char* name() const override { return "analytic"; }
    std::string description() const override;
    MethodCaps caps() const override;
    std::string notice(const LightSetup& light) const override;
    ChainOptions options(const LightSetup&, const LightData*, const ChainOptions*) const override;
    ChainOutputs addChain(rg::RenderGraph& graph, ChainLights lights,
                          const CompositeTarget& target) const override;
    std::string summary(const ChainConfig&) const override;
};

}  // namespace ls
