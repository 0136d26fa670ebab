#pragma once
// A method of the frame graph as one unit: what it can take, why it refuses a light, what it
// prepares on the CPU, the nodes of one light's chain, and the line that says what it built. Every
// method implements this in its own folder (passes/<method>/) and has one line in
// lightscatter/methods.inc, from which the registry and the public enum are made; the plugin API
// validates the frame, chooses each light's method, keeps each light's state by its id and builds
// the frame's graph from the chains, and knows no method's nodes.
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "chain_options.h"
#include "light_setup.h"
#include "lightscatter/settings.h"
#include "rendergraph/render_graph.h"
#include "shared/composite_target.h"
#include "shared/frame_history.h"
#include "shared/light_frame.h"
#include "shared/shared_state.h"

namespace lightscatter {
struct StepCounts;
}

namespace ls {

// What a method takes (the plugin's refusals and MethodInfo are made from it).
struct MethodCaps {
    bool directional = true, spot = true, point = true;
    bool shadowMap = true;             // casts shadows from a light's shadow map
    bool cubeShadow = false;           // samples a point light's six-face shadow map
    bool lightColor = true;            // a light color (cookie) with a shadow map
    bool unshadowedLightColor = true;  // ... and without one
    // Settings beyond docs/model.md it honours (Settings' comments).
    bool noise = false;
    bool simplifiedModel = false;
    bool skipsShadowSampling = false;
    bool readsOccluders = false;  // FrameDescription::occluders (the beam trees)
    bool media = false;           // a non-uniform medium (height fog, fog volumes)
    bool countsSteps = false;     // DebugOptions::countSteps: a counting variant of its march
    // Its textures depend on the profile's sizes: budget() reports it.
    bool profileSized = false;
    // Every light of the frame goes through one chain (ChainLights): the froxel grid.
    bool onePerFrame = false;
    // A one-per-frame chain that writes its 3D result into ChainInputs::volumeOut when given.
    bool exportsVolume = false;
    bool keepsHistory = false;  // a frame's output may depend on earlier frames'
};

// One light's chain in the frame graph's configuration: what decides its nodes, their textures
// and their shader builds. Equal configurations build equal chains.
struct ChainConfig {
    LightType light = LightType::Directional;
    bool shadowed = false;
    uint32_t shadowMapSize = 0;
    ScatterSpec spec;      // the light's shader options (scatterSpec())
    ChainOptions options;  // the method's own (its Options struct)
    bool operator==(const ChainConfig&) const = default;
};

// A light's shader options, from what the frame holds.
ScatterSpec scatterSpec(const LightSetup& light);

// CPU work prepare() did for this frame, for the frame's report.
struct CpuWork {
    std::string name;
    double milliseconds = 0;
};

// What one light's chain reads. Images the frame lacks are invalid handles.
struct ChainInputs {
    Shared shared;  // the device's samplers and pipelines (null for the budget's graph)
    rg::HostDataRef<LightFrame> values;  // the light's values, given to each record()
    rg::BufferRef constants;             // the light's FrameConstants, uploaded
    rg::ImageRef depth;                  // the engine's depth
    rg::ImageRef shadowMap;              // the light's depth
    rg::ImageRef lightColor;             // its light-space color
    rg::ImageRef table;                  // its point-light table, where readsTable() asked for one
    rg::ImageRef noise;  // the frame's tiling noise, where readsNoise() asked for it
    VkExtent2D screen{0, 0};
    VkFormat depthStencil = VK_FORMAT_UNDEFINED;  // the stencil textures' format
    VkFormat coordinateFormat = VK_FORMAT_R32G32_SFLOAT;
    rg::BufferRef stepCounts;  // cleared, when the frame counts epipolar's steps; else invalid
    // The keys the graph keeps what outlives a frame under (RenderGraph::persistentImage,
    // historyImages): the light's own (its table, its method's images), and the frame's (a
    // one-per-frame method's history), each given to every record().
    rg::HostDataRef<rg::PersistentKey> key, frameKey;
    // The frame before's constants, for a method that reprojects its history.
    rg::HostDataRef<PreviousFrame> previous;
    // The engine's 3D image for the chain's 3D result (FrameDescription::volumeOut), for a method
    // that exportsVolume; else invalid.
    rg::ImageRef volumeOut;
};

// The 3D image a method that exportsVolume writes into ChainInputs::volumeOut: its extent in
// texels, the screen pixels a column covers, and the camera-space depths its slices span.
struct VolumeLayout {
    uint32_t width = 0, height = 0, depth = 0;
    uint32_t tile = 0;
    float nearZ = 0.0f, farZ = 0.0f;
    std::string rule;  // how the extent follows from the screen and the settings, for a refusal
};

// One light's part of a chain: what it reads and how it is built.
struct ChainLight {
    ChainInputs in;
    ChainConfig config;
};

// The lights of one chain: one light, or for a one-per-frame method (MethodCaps::onePerFrame)
// every light reaching the view, in the frame's order.
using ChainLights = std::span<const ChainLight>;

// The one light of a per-light method's chain; a logic error for any other count.
const ChainLight& onlyLight(ChainLights lights, const char* method);

// What a chain leaves: a screen Lin for the composite, or the target's new versions where the
// chain composited its Lin itself.
struct ChainOutputs {
    rg::ImageRef lin;
    bool composited = false;
    CompositeOutputs target;
    rg::BufferRef stepCounts;  // the counter's new version, when the chain counted
};

class MethodUnit {
  public:
    virtual ~MethodUnit() = default;
    virtual const char* name() const = 0;         // the CLI's and the report's name
    virtual std::string description() const = 0;  // one line
    virtual MethodCaps caps() const = 0;
    // Its own settings' field table (Settings::<its member>), or none.
    virtual std::vector<lightscatter::SettingsField> settingsFields() const { return {}; }
    // Named settings of it, as engines ship it (froxels' "froxels-unreal"), or none.
    virtual std::vector<lightscatter::MethodPreset> presets() const { return {}; }
    // Seed 000's published memory and time for a profile, where the method has them.
    virtual std::optional<lightscatter::SeedFigure> seedFigure(lightscatter::Profile) const {
        return std::nullopt;
    }
    // Why the method cannot honour this light beyond what its caps say (the plugin refuses what
    // they rule out), in one line naming the field and the rule (the API adds "lightscatter: ");
    // empty when it can.
    virtual std::string refusal(const LightSetup&) const { return {}; }
    // An assumption of the method the light or medium breaks, and what it costs; empty if none.
    virtual std::string notice(const LightSetup&) const { return {}; }
    // Whether the chain samples the light's point-light table (made and kept by the plugin).
    virtual bool readsTable(const LightSetup&) const { return false; }
    // Whether the chain samples the frame's tiling noise (the engine's, or the plugin's own).
    virtual bool readsNoise(const LightSetup&) const { return false; }
    // A method that countsSteps (DebugOptions::countSteps): the bytes of the counter its counting
    // chain adds into for this light (the frame's one buffer holds the most any light needs,
    // cleared before the chains), and once the GPU is done, the frame's counts from that buffer.
    virtual uint64_t stepCountBytes(const LightSetup&) const { return 0; }
    virtual void readStepCounts(const void* counters, uint64_t bytes,
                                lightscatter::StepCounts& out) const;
    // An ambient term the method adds beside a point or spot light's inverse square (1/m^2, seed
    // 002's), for the bound Lin is stored under (plugin_api/src/lin_storage.h); 0: the model's.
    virtual float ambient(const LightSetup&) const { return 0.0f; }
    // The light's state across frames; null when the method keeps none.
    virtual std::unique_ptr<LightData> makeData() const { return nullptr; }
    // This frame's CPU work for the light, into `data` (made by makeData()); `frame`'s constants
    // are filled already.
    virtual std::vector<CpuWork> prepare(LightData*, LightFrame&, const LightSetup&) const {
        return {};
    }
    // The chain's options for the light; `data` is prepare()'s (null for the budget), `previous`
    // the options the light's chain had in the last graph (null: none, or another method's).
    virtual ChainOptions options(const LightSetup& light, const LightData* data,
                                 const ChainOptions* previous) const = 0;
    // Adds a chain: one light's, or a one-per-frame method's for all its lights (ChainLights).
    // `target` is where a chain that composites itself writes (never add-only for a one-per-frame
    // chain, the frame's only one); a chain that returns a screen Lin leaves the composite to the
    // frame.
    virtual ChainOutputs addChain(rg::RenderGraph& graph, ChainLights lights,
                                  const CompositeTarget& target) const = 0;
    // A method that exportsVolume: the volume it writes for the light's settings on a screen of
    // `screen` texels. Only asked of such a method.
    virtual VolumeLayout exportedVolume(const LightSetup& light, VkExtent2D screen) const;
    // Which nodes the chain was built from, and why, in one line.
    virtual std::string summary(const ChainConfig& config) const = 0;
    // What changed this frame without a rebuild, appended to the report's reason (the cube faces
    // reaching the view); empty if nothing.
    virtual std::string frameNote(const LightFrame&, const ChainConfig&) const { return {}; }
};

// Each method's unit, defined in its own folder; the registry lists them in methods.inc's order.
#define LIGHTSCATTER_METHOD(Enum, Type, member) const MethodUnit& methodUnit##Enum();
#define LIGHTSCATTER_METHOD_WITHOUT_SETTINGS(Enum) const MethodUnit& methodUnit##Enum();
#include "lightscatter/methods.inc"

}  // namespace ls
