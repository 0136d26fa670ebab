#pragma once
// Which nodes a frame needs, and the graph made of them. A graph is rebuilt only when its
// configuration changes (screen, profile sizes, method, light type, shadowing, optional images,
// formats, layouts); everything else changes through the frame constants.
#include <memory>
#include <string>
#include <vector>

#include "shared/node_inputs.h"
#include "beam_tree_hybrid/beam_tree_nodes.h"
#include "slices/slice_nodes.h"
#include "lightscatter.h"
#include "rendergraph/device_caps.h"
#include "rendergraph/render_graph.h"

namespace lightscatter::detail {

struct ImportState {
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{0, 0};
    VkImageUsageFlags usage = 0;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout finalLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    uint32_t arrayLayers = 1;
    bool operator==(const ImportState& o) const {
        return format == o.format && extent.width == o.extent.width &&
               extent.height == o.extent.height && usage == o.usage && layout == o.layout &&
               finalLayout == o.finalLayout && arrayLayers == o.arrayLayers;
    }
};

// One light's chain in a frame of several lights (GraphConfig::lights).
struct LightChainConfig {
    ls::LightKind light = ls::LightKind::Directional;
    bool shadowed = false;
    bool touchesView = true;
    bool minMaxTrees = true;
    bool fixup = true;             // the light's own settings (LightInput::settings, or the frame's)
    bool inscatterRefinement = false;
    uint32_t slices = 0, samples = 0;
    uint32_t shadowMapSize = 0;
    ImportState shadowMap, lightColor, table;  // format UNDEFINED: absent
    bool operator==(const LightChainConfig& o) const {
        return light == o.light && shadowed == o.shadowed && touchesView == o.touchesView &&
               minMaxTrees == o.minMaxTrees && fixup == o.fixup &&
               inscatterRefinement == o.inscatterRefinement && slices == o.slices &&
               samples == o.samples && shadowMapSize == o.shadowMapSize && shadowMap == o.shadowMap &&
               lightColor == o.lightColor && table == o.table;
    }
};

struct GraphConfig {
    Method method = Method::Epipolar;
    ls::LightKind light = ls::LightKind::Directional;
    bool shadowed = false;
    bool touchesView = true;
    bool minMaxTrees = true;
    bool fixup = true;
    bool inscatterRefinement = false;  // epipolar: a second march where marched samples differ
    uint32_t slices = 0, samples = 0, shadowMapSize = 0;
    VkExtent2D screen{0, 0};
    VkFormat depthStencil = VK_FORMAT_UNDEFINED;
    VkFormat coordinates = VK_FORMAT_R32G32_SFLOAT;  // epipolar's coordinate texture (coordinateFormat)
    ImportState depth, color, shadowMap, lightColor, inscatterOut;  // format UNDEFINED: absent
    ImportState table;
    bool extinction = true;         // betaT > 0 in some channel: the composite has work
    uint32_t coneSamples = 32;      // cone-march
    bool coneLimited = true;
    bool coneJitter = false;
    bool shadowSampling = true;     // false: cone-march's low-end mode
    ls::SliceAccumulation sliceTarget = ls::SliceAccumulation::Float16;  // slices
    uint32_t sliceBlur = 0;
    bool sliceDither = false;
    bool reversedZ = false;         // the camera's depth convention (slices depth-tests)
    uint32_t beamCapacity = 0;      // beam-tree-analytic: the triangle buffer, in points
    bool noise = false;             // slices samples a noise texture: the engine's (`noise` given) or ours
    ImportState engineNoise;        // format UNDEFINED: the plugin's own noise
    bool poisonTransients = false;
    // Epipolar's step counter (DebugOptions::countSteps): the marches' counting variant, adding
    // into FrameGraph::stepCounts.
    bool countSteps = false;
    // Several lights (epipolar or brute-force): one chain each, in this order; when not empty, the
    // single light's fields above (light, shadowed, touchesView, minMaxTrees, shadowMapSize,
    // shadowMap, lightColor, table) are unused.
    std::vector<LightChainConfig> lights;
    bool operator==(const GraphConfig& o) const;
};

struct FrameGraph {
    std::unique_ptr<rg::RenderGraph> graph;
    rg::ImageRef depth, color, shadowMap, lightColor, inscatterOut, table, noise;
    std::string summary;  // which nodes were chosen, and why
    struct LightImages {
        rg::ImageRef shadowMap, lightColor, table;
    };
    std::vector<LightImages> lights;  // several lights: each one's imports (GraphConfig::lights)
    // The step counter the plugin imports (one buffer per frame in flight; ls::stepCountBytes of
    // the slices); invalid without GraphConfig::countSteps or without an epipolar march.
    rg::BufferRef stepCounts;
};

ls::SliceAccumulation sliceAccumulation(SliceTarget target);

// The step counter's import: written by the frame's passes, read by the host once it is done.
rg::ImportedBuffer stepCountImport(VkBuffer buffer, uint32_t slices);

rg::ImportedImage importDescription(const ImageInput& in);
rg::ImportedImage importDescription(const ImportState& s);
// An image the plugin owns across frames (the point-light table, the tiling noise): filled
// outside the frame, sampled by fragment and compute shaders within it, left read-only.
rg::ImportedImage persistentImport(const ImportState& s, VkImage image);
// The plugin's own tiling noise, as the frame graph imports it.
ImportState ownNoiseState();

// The format of the stencil textures (epipolar's sample marking, the fix-up's pixel marking),
// which hold stencil only: S8 where the device renders to it (a quarter of a depth-stencil texel),
// else D24S8, else D32S8; UNDEFINED when none is an attachment format.
VkFormat stencilFormat(const rg::DeviceCaps& caps);

// The format of epipolar's coordinate texture (each sample's NDC position): R16G16_UNORM where the
// device renders to it (2 / 65535 of NDC: 0.04 pixel at 2560 pixels across), else R32G32_SFLOAT.
VkFormat coordinateFormat(const rg::DeviceCaps& caps);

// The plugin's own tiling noise, when a slices frame uses it without an engine image.
inline constexpr VkExtent2D kNoiseExtent{256, 256};
inline constexpr VkFormat kNoiseFormat = VK_FORMAT_R8G8_UNORM;

// `slices`: where the planes go, updated by the plugin before each frame (null for the budget).
// `beams`: the beam tree's triangles, likewise (beam-tree-analytic).
// `lightShared`: several lights, each one's state (its constants and shader options), in the order
// of config.lights; empty for the budget.
FrameGraph buildFrameGraph(const GraphConfig& config, const ls::Shared& shared,
                           ls::SlicePlacementRef slices = nullptr, ls::BeamTreeFrameRef beams = nullptr,
                           const std::vector<ls::Shared>& lightShared = {});

}  // namespace lightscatter::detail
