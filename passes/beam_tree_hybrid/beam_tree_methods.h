#pragma once
// Seed 004's two methods as methods of the frame graph (method_unit.h): a beam tree of the frame's
// occluders built on the CPU each frame, and the lit space in closed form (beam-tree-analytic) or
// sampled by planes without shadow look-ups (beam-tree-sampling); dark space is never drawn.
#include <memory>

#include "beam_tree_frame.h"
#include "shared/method_unit.h"

namespace ls {

class BeamTreeMethod : public MethodUnit {
  public:
    struct Options {
        uint32_t capacityPoints = 0;  // the triangle buffer; grows in powers of two, never shrinks
        bool reversedZ = false;
        bool operator==(const Options&) const = default;
    };
    MethodCaps caps() const override;
    std::string refusal(const LightSetup& light) const override;
    std::string notice(const LightSetup& light) const override;
    std::unique_ptr<LightData> makeData() const override;
    std::vector<CpuWork> prepare(LightData* data, LightFrame&,
                                 const LightSetup& light) const override;
    // The closed forms: the analytic method's lit pyramids, and both methods' planes' slabs.
    bool readsTable(const LightSetup&) const override { return true; }
    ChainOptions options(const LightSetup& light, const LightData* data,
                         const ChainOptions* previous) const override;
    // The sampling planes this frame placed (with Settings::planes.spacing their count varies).
    std::string frameNote(const LightFrame& frame, const ChainConfig& config) const override;

  protected:
    virtual LitSpace litSpace() const = 0;
};

class BeamTreeAnalyticMethod final : public BeamTreeMethod {
  public:
    const char* name() const override { return "beam-tree-analytic"; }
    std::string description() const override;
    MethodCaps caps() const override;
    ChainOutputs addChain(rg::RenderGraph& graph, ChainLights lights,
                          const CompositeTarget& target) const override;
    std::string summary(const ChainConfig& config) const override;

  protected:
    LitSpace litSpace() const override { return LitSpace::ClosedForm; }
};

class BeamTreeSamplingMethod final : public BeamTreeMethod {
  public:
    const char* name() const override { return "beam-tree-sampling"; }
    std::string description() const override;
    MethodCaps caps() const override;
    ChainOutputs addChain(rg::RenderGraph& graph, ChainLights lights,
                          const CompositeTarget& target) const override;
    std::string summary(const ChainConfig& config) const override;

  protected:
    LitSpace litSpace() const override { return LitSpace::Planes; }
};

}  // namespace ls
