#pragma once
// Which nodes a frame needs, and the graph made of them: the engine's images, one chain per light
// whose volume reaches the view (the frame's method builds it, shared/method_unit.h), and the
// composite. A graph is rebuilt only when its configuration changes (screen, formats, layouts, the
// method, each light's kind, shadowing and method options); everything else changes through the
// frame constants.
#include <memory>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "rendergraph/device_caps.h"
#include "rendergraph/render_graph.h"
#include "rendergraph/vk_equality.h"
#include "shared/method_unit.h"

namespace lightscatter::detail {

// What of an imported image decides the graph (its handle and stages do not).
struct ImportState {
    VkFormat format = VK_FORMAT_UNDEFINED;  // UNDEFINED: absent
    VkExtent2D extent{0, 0};
    VkImageUsageFlags usage = 0;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout finalLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    uint32_t arrayLayers = 1;
    uint32_t depth = 1;  // a 3D image's slices (the frame's history)
    bool operator==(const ImportState&) const = default;
    bool given() const { return format != VK_FORMAT_UNDEFINED; }
};
ImportState importState(const ImageInput& in);

// One light of the frame.
struct LightGraphConfig {
    const ls::MethodUnit* method = nullptr;  // the light's method (the registry's)
    ls::ChainConfig chain;
    bool touchesView = true;  // false: no chain (its images are still imported)
    bool noise = false;       // its chain samples the frame's tiling noise
    bool table = false;       // its chain samples its point-light table
    ImportState shadowMap, lightColor;
    bool operator==(const LightGraphConfig&) const = default;
};

struct GraphConfig {
    VkExtent2D screen{0, 0};
    // The screen above is the plugin's maxRenderSize: each frame's engine images (depth, color,
    // inscatterOut) may be smaller, and the passes over the screen render over theirs.
    bool dynamicScreen = false;
    VkFormat depthStencil = VK_FORMAT_UNDEFINED;
    VkFormat coordinates =
        VK_FORMAT_R32G32_SFLOAT;             // epipolar's coordinate texture (coordinateFormat)
    ImportState depth, color, inscatterOut;  // color: absent where the engine composites itself
    ImportState transmittanceOut;
    // The device was created with dualSrcBlend: a split composite blends into an attachment color
    // in one draw (passes/shared/shared_nodes.h, addSplitComposite).
    bool dualSourceBlend = false;
    // The device blends into the color's format as an attachment (COLOR_ATTACHMENT_BLEND): with
    // dualSourceBlend and the color's COLOR_ATTACHMENT usage, a fragment pass that composites a
    // storage color blends into it instead (ls::CompositeTarget::blend).
    bool colorBlends = false;
    ImportState noise;       // the engine's noise, where a chain samples it
    bool ownNoise = false;   // a chain samples the plugin's own tiling noise instead
    bool extinction = true;  // betaT > 0 in some channel: the composite has work
    bool poisonTransients = false;
    // DebugOptions::countSteps: the counting chains (a method that countsSteps) add into
    // FrameGraph::stepCounts, of stepCountBytes (the most of any light), and `stepCounter` reads
    // it.
    bool countSteps = false;
    uint64_t stepCountBytes = 0;
    const ls::MethodUnit* stepCounter = nullptr;
    // The engine's image for a one-per-frame method's 3D result (FrameDescription::volumeOut).
    ImportState volumeOut;
    std::vector<LightGraphConfig> lights;  // in the frame's order
    bool operator==(const GraphConfig&) const = default;
};

struct FrameGraph {
    std::unique_ptr<rg::RenderGraph> graph;
    rg::ImageRef depth, color, inscatterOut, transmittanceOut, noise;
    struct LightImages {
        rg::ImageRef shadowMap, lightColor;
        rg::HostDataRef<ls::LightFrame> values;  // the light's values, given to each record()
        rg::HostDataRef<rg::PersistentKey> key;  // its identity: what the graph keeps for it
    };
    std::vector<LightImages> lights;  // each light's imports (GraphConfig::lights)
    std::string summary;              // which nodes were chosen, and why
    // The step counter the plugin imports (one buffer per frame in flight); invalid without
    // GraphConfig::countSteps.
    rg::BufferRef stepCounts;
    // The frame's key, under which the graph keeps what is the frame's rather than a light's (the
    // plugin's noise, a one-per-frame method's history), and the frame before's constants.
    rg::HostDataRef<rg::PersistentKey> frameKey;
    rg::HostDataRef<ls::PreviousFrame> previous;
    rg::ImageRef volumeOut;  // GraphConfig::volumeOut's import
};

// The step counter's import: written by the frame's passes, read by the host once it is done.
rg::ImportedBuffer stepCountImport(VkBuffer buffer, uint64_t bytes);

rg::ImportedImage importDescription(const ImageInput& in);
rg::ImportedImage importDescription(const ImportState& s);
// The format of the stencil textures (epipolar's sample marking, the fix-up's pixel marking),
// which hold stencil only: S8 where the device renders to it (a quarter of a depth-stencil texel),
// else D24S8, else D32S8; UNDEFINED when none is an attachment format.
VkFormat stencilFormat(const rg::DeviceCaps& caps);

// The format of epipolar's coordinate texture (each sample's NDC position): R16G16_UNORM where the
// device renders to it (2 / 65535 of NDC: 0.04 pixel at 2560 pixels across), else R32G32_SFLOAT.
VkFormat coordinateFormat(const rg::DeviceCaps& caps);

// `shared`: the device's samplers and pipelines; null for the budget, whose graph never records.
// Nothing of a frame goes in: each record() gives the lights' values (FrameGraph::lights[i].values)
// and the noise's (makeNoise), so the graph may be kept for later frames.
FrameGraph buildFrameGraph(const GraphConfig& config, const ls::Shared& shared = nullptr);

}  // namespace lightscatter::detail
