#pragma once
// Brute force as a method of the frame graph (method_unit.h): every pixel marches its own ray,
// the GPU reference; the closed form for an unshadowed light.
#include "shared/method_unit.h"

namespace ls {

class BruteForceMethod final : public MethodUnit {
  public:
    const char* name() const override { return "brute-force"; }
    std::string description() const override;
    MethodCaps caps() const override;
    bool readsTable(const LightSetup& light) const override;
    ChainOptions options(const LightSetup&, const LightData*, const ChainOptions*) const override;
    ChainOutputs addChain(rg::RenderGraph& graph, ChainLights lights,
                          const CompositeTarget& target) const override;
    std::string summary(const ChainConfig& config) const override;
};

}  // namespace ls
