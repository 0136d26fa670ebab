#pragma once
// Seed 003's fixed-count march as a method of the frame graph (method_unit.h), with its low-end
// mode that skips the shadow map.
#include "cone_march_options.h"
#include "shared/method_unit.h"
#include "shared/settings_table.h"

namespace ls {

class ConeMarchMethod final : public MethodUnit {
  public:
    struct Options {
        ConeMarchOptions march;
        bool shadowSampling = true;
        bool operator==(const Options&) const = default;
    };
    const char* name() const override { return "cone-march"; }
    std::string description() const override;
    MethodCaps caps() const override;
    std::vector<SettingsField> settingsFields() const override;
    ChainOptions options(const LightSetup& light, const LightData*,
                         const ChainOptions*) const override;
    ChainOutputs addChain(rg::RenderGraph& graph, ChainLights lights,
                          const CompositeTarget& target) const override;
    std::string summary(const ChainConfig& config) const override;
};

}  // namespace ls
