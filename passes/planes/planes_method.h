#pragma once
// Seed 002's view-aligned planes as a method of the frame graph (method_unit.h): the planes
// placed on the CPU each frame, blended into an accumulation target, resolved into Lin.
#include <memory>

#include "plane_geometry.h"
#include "shared/method_unit.h"
#include "shared/settings_table.h"

namespace ls {

class PlanesMethod final : public MethodUnit {
  public:
    struct Options {
        PlaneTarget target = PlaneTarget::Float16;
        uint32_t blur = 0;
        bool dither = false;
        bool noise = false;
        bool shadowSampling = true;
        bool reversedZ = false;  // the camera's depth convention (the planes depth-test)
        bool operator==(const Options&) const = default;
    };
    const char* name() const override { return "planes"; }
    std::string description() const override;
    MethodCaps caps() const override;
    std::vector<SettingsField> settingsFields() const override;
    std::string refusal(const LightSetup& light) const override;
    bool readsNoise(const LightSetup& light) const override { return noisy(light); }
    float ambient(const LightSetup& light) const override { return light.settings.planes.ambient; }
    std::unique_ptr<LightData> makeData() const override;
    std::vector<CpuWork> prepare(LightData* data, LightFrame&,
                                 const LightSetup& light) const override;
    ChainOptions options(const LightSetup& light, const LightData*,
                         const ChainOptions*) const override;
    ChainOutputs addChain(rg::RenderGraph& graph, ChainLights lights,
                          const CompositeTarget& target) const override;
    std::string summary(const ChainConfig& config) const override;
    // The planes this frame placed (with Settings::planes.spacing their count varies).
    std::string frameNote(const LightFrame& frame, const ChainConfig& config) const override;
};

}  // namespace ls
