#pragma once
// Seed 000's epipolar sampling as a method of the frame graph (method_unit.h): the chain of
// epipolar_nodes.h per shadowed light (a point light's cube map: its six faces in each pass that
// reads it), and the closed form for an unshadowed one.
#include "shared/method_unit.h"
#include "shared/settings_table.h"

namespace ls {

class EpipolarMethod final : public MethodUnit {
  public:
    struct Options {
        uint32_t slices = 0, samples = 0;
        uint32_t marchPhases = 1;  // the march's order (marchPhases, epipolar_constants.h)
        bool minMaxTrees = true;
        bool fixup = true;
        bool inscatterRefinement = false;  // a second march where marched samples differ
        bool marchList = false;            // marchesFromList (epipolar_constants.h)
        bool operator==(const Options&) const = default;
    };
    const char* name() const override { return "epipolar"; }
    std::string description() const override;
    MethodCaps caps() const override;
    std::vector<SettingsField> settingsFields() const override;
    std::optional<lightscatter::SeedFigure> seedFigure(lightscatter::Profile p) const override;
    bool readsTable(const LightSetup& light) const override;
    uint64_t stepCountBytes(const LightSetup& light) const override;
    void readStepCounts(const void* counters, uint64_t bytes,
                        lightscatter::StepCounts& out) const override;
    std::unique_ptr<LightData> makeData() const override;
    std::vector<CpuWork> prepare(LightData* data, LightFrame&,
                                 const LightSetup& light) const override;
    ChainOptions options(const LightSetup& light, const LightData*,
                         const ChainOptions*) const override;
    ChainOutputs addChain(rg::RenderGraph& graph, ChainLights lights,
                          const CompositeTarget& target) const override;
    std::string summary(const ChainConfig& config) const override;
    std::string frameNote(const LightFrame& frame, const ChainConfig& config) const override;
};

}  // namespace ls
