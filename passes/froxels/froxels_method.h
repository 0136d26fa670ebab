#pragma once
// Froxels as a method of the frame graph (method_unit.h): the froxel volumetric fog engines ship,
// for comparison with the seeds' methods on the same frame. One per frame: every light of the frame
// is injected into one grid, integrated once and applied once.
#include "froxel_nodes.h"
#include "shared/method_unit.h"
#include "shared/settings_table.h"

namespace ls {

class FroxelsMethod final : public MethodUnit {
  public:
    struct Options {
        bool operator==(const Options&) const = default;
        FroxelSettings grid;
    };
    const char* name() const override { return "froxels"; }
    std::string description() const override;
    MethodCaps caps() const override;
    std::vector<SettingsField> settingsFields() const override;
    std::vector<lightscatter::MethodPreset> presets() const override;
    std::string refusal(const LightSetup& light) const override;
    // A point or spot light's froxels take their slices in closed form (inject.comp's LS_SLAB), in
    // a homogeneous medium under the full light model.
    bool readsTable(const LightSetup& light) const override;
    ChainOptions options(const LightSetup& light, const LightData*,
                         const ChainOptions*) const override;
    ChainOutputs addChain(rg::RenderGraph& graph, ChainLights lights,
                          const CompositeTarget& target) const override;
    VolumeLayout exportedVolume(const LightSetup& light, VkExtent2D screen) const override;
    std::string summary(const ChainConfig& config) const override;
};

}  // namespace ls
