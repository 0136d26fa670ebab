#pragma once
// The one function from a checked frame to its graph's configuration, shared by the plugin (each
// frame) and budget() (a frame it describes without a device).
#include <vector>

#include "frame_graph.h"
#include "frame_setup.h"

namespace lightscatter::detail {

// What of the engine's images decides the graph: the frame's, and each light's (absent: format
// UNDEFINED).
struct FrameImports {
    ImportState depth, color, inscatterOut, transmittanceOut, noise, volumeOut;
    std::vector<ImportState> shadowMaps, lightColors;  // one per light
};
// Its lights' in `v`'s order.
FrameImports frameImports(const FrameDescription& frame, const ValidatedFrame& v);

struct GraphOptions {
    VkFormat depthStencil = VK_FORMAT_UNDEFINED;
    VkFormat coordinates = VK_FORMAT_R32G32_SFLOAT;
    bool poisonTransients = false;
    bool countSteps = false;  // DebugOptions::countSteps: where the method counts (epipolar)
    // PluginCreateInfo::maxRenderSize (zero: none): the graph is built for it, and a frame's screen
    // may be any size within it.
    VkExtent2D maxScreen{0, 0};
    bool dualSourceBlend = false;  // the device was created with dualSrcBlend
    bool colorBlends = false;      // the device blends into the frame's color format
};

// `methods`: each light's; `data`: each light's method state after prepare() (empty for the
// budget); `previous`: each light's chain options in the last frame that ran it with the same
// method (null: none), which a method may grow from (the beam tree's buffer).
GraphConfig graphConfig(const ValidatedFrame& frame,
                        const std::vector<const ls::MethodUnit*>& methods,
                        const FrameImports& images, const GraphOptions& options,
                        const std::vector<const ls::LightData*>& data = {},
                        const std::vector<const ls::ChainOptions*>& previous = {});

}  // namespace lightscatter::detail
