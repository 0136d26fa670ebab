#pragma once
// What the scattering passes share for as long as the plugin lives: the device, samplers and the
// pipelines built so far; and the shader options of a light (ScatterSpec), part of its chain's
// configuration.
#include <array>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include "device_capabilities.h"
#include "frame_constants.h"
#include "rendergraph/pipeline.h"
#include "rendergraph/pipeline_key.h"
#include "scattering_params.h"

namespace ls {

// Specialisation constants of shaders/shared/frame.glsl, and the light's options that choose a
// shader variant (its light color, a point light's cube map). Fixed for a graph: a change builds
// (or finds) another. A method's own variants are in its options (ChainConfig::options).
struct ScatterSpec {
    LightType light = LightType::Directional;
    MiePhase phase = MiePhase::CornetteShanks;
    bool lightColor = false;
    bool bilinearShadow = true;
    bool simplifiedModel = false;  // seed 004's light model (Settings::lightModel)
    bool cubeShadow = false;       // a point light's six-face shadow map (a 2D array of 6 layers)
    int media = 0;                 // a non-uniform medium's parts: LS_MEDIA_* bits (bindings.h)
    rg::Specialization constants() const;
    // The medium's constant alone (empty for a homogeneous medium), for the shaders that read
    // nothing else of the light's options (the composite's transmittance).
    rg::Specialization mediaConstants() const;
    bool operator==(const ScatterSpec&) const = default;
};

// The pipelines built so far, keyed by their whole description (rendergraph/pipeline_key.h): a
// pass asks for the pipeline it describes, and any field that differs gives another pipeline. The
// name labels the pipeline (debug names, errors) and is no part of the key.
class PipelineLibrary {
  public:
    explicit PipelineLibrary(const rg::Device& device) : device_(device) {}
    const rg::Pipeline& compute(const std::string& name, rg::ShaderCode code,
                                const std::vector<rg::Binding>& bindings, uint32_t pushBytes,
                                const rg::Specialization& spec);
    const rg::Pipeline& graphics(const std::string& name, const rg::GraphicsPipelineDesc& desc);
    size_t size() const {
        std::lock_guard lock(mutex_);
        return pipelines_.size();
    }

  private:
    const rg::Device& device_;
    // Plugins on one device share the library and may record on several threads.
    mutable std::mutex mutex_;
    std::map<rg::PipelineKey, rg::Pipeline> pipelines_;
};

// What every pass of every light shares: the device, what of its optional features the engine
// enabled, its samplers and the pipelines built so far. Nothing of a frame: a pass reads its
// frame's values from the host data it declared (light_frame.h), and its shader options from its
// inputs, fixed when the graph is built.
struct SharedState {
    explicit SharedState(const rg::Device& d, DeviceCapabilities c = {})
        : device(d), capabilities(c), samplers(d), pipelines(d) {}
    SharedState(const SharedState&) = delete;
    SharedState& operator=(const SharedState&) = delete;
    const rg::Device& device;
    const DeviceCapabilities capabilities;
    rg::Samplers samplers;
    PipelineLibrary pipelines;
};

using Shared = std::shared_ptr<SharedState>;

// The samplers a node's binding table names when it is declared: null handles for a graph
// without a device (the budget's, whose passes never record).
const rg::Samplers& samplersOf(const Shared& shared);

}  // namespace ls
