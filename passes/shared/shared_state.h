#pragma once
// State the scattering passes share for as long as the plugin lives: the device, samplers, the
// pipelines built so far, and this frame's constants (updated before each recording; the upload
// pass copies them into the command buffer, so frames in flight never share them).
#include <array>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "frame_constants.h"
#include "rendergraph/pipeline.h"
#include "rendergraph/pipeline_key.h"
#include "scattering_params.h"

namespace ls {

// Specialisation constants of shaders/shared/frame.glsl, and the options that choose a
// shader variant (min/max trees).
struct ScatterSpec {
    LightType light = LightType::Directional;
    MiePhase phase = MiePhase::CornetteShanks;
    bool minMaxTrees = true;
    bool lightColor = false;
    bool bilinearShadow = true;
    bool simplifiedModel = false;  // seed 004's light model (Settings::lightModel)
    bool cubeShadow = false;       // a point light's six-face shadow map (a 2D array of 6 layers)
    rg::Specialization constants() const;
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
    size_t size() const { return pipelines_.size(); }

  private:
    const rg::Device& device_;
    std::map<rg::PipelineKey, rg::Pipeline> pipelines_;
};

// What every light's state shares: the samplers and the pipelines built so far.
struct SharedResources {
    explicit SharedResources(const rg::Device& d) : samplers(d), pipelines(d) {}
    rg::Samplers samplers;
    PipelineLibrary pipelines;
};

// One light's view of the shared state: its constants and shader options, over the resources
// every light shares. A frame of several lights has one per light (sibling()).
struct SharedState {
    explicit SharedState(const rg::Device& d)
        : resources(std::make_shared<SharedResources>(d)),
          device(d),
          samplers(resources->samplers),
          pipelines(resources->pipelines) {}
    SharedState(const SharedState&) = delete;
    SharedState& operator=(const SharedState&) = delete;
    // Another light's state over the same device, samplers and pipelines.
    static std::shared_ptr<SharedState> sibling(const SharedState& s) {
        return std::shared_ptr<SharedState>(new SharedState(s.resources, s.device));
    }
    std::shared_ptr<SharedResources> resources;
    const rg::Device& device;
    rg::Samplers& samplers;
    PipelineLibrary& pipelines;
    FrameConstants constants{};
    ScatterSpec spec;
    // A point light's cube shadow map under epipolar: one state per face (+X, -X, +Y, -Y, +Z, -Z),
    // whose constants carry the face's matrix as lightViewProj and its index in cubeFace.x.
    // A face whose frustum misses the view has constants.cubeFace.y 0: its passes stay in the graph
    // (a face moving into view rebuilds nothing) and record no work.
    std::array<std::shared_ptr<SharedState>, 6> cubeFaces;
    bool inView() const { return constants.cubeFace.y > 0.5f; }

  private:
    SharedState(std::shared_ptr<SharedResources> r, const rg::Device& d)
        : resources(std::move(r)),
          device(d),
          samplers(resources->samplers),
          pipelines(resources->pipelines) {}
};

using Shared = std::shared_ptr<SharedState>;

// The samplers a node's binding table names when it is declared: null handles for a graph
// without a device (the budget's, whose passes never record).
const rg::Samplers& samplersOf(const Shared& shared);

}  // namespace ls
