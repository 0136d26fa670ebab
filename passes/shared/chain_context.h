#pragma once
// What every node of one light's chain reads, prepared by the plugin for one frame graph: the
// light's constants and values with the frame's depth and formats (ChainContext), and the light's
// images (LightImages). A node's Inputs struct holds the parts it reads; no node writes any of it.
// The textures the nodes make are returned by the nodes that write them and passed to the nodes
// that read them.
#include <vulkan/vulkan.h>

#include "light_frame.h"
#include "rendergraph/render_graph.h"
#include "shared_state.h"

namespace ls {

// One light's chain: the frame's depth and screen, seen through that light's constants.
struct ChainContext {
    Shared shared;     // the device's samplers and pipelines (null for the budget's graph)
    ScatterSpec spec;  // the light's shader options
    rg::HostDataRef<LightFrame> values;  // the light's values of the frame being recorded
    rg::BufferRef constants;             // the light's constants, uploaded by an earlier pass
    rg::ImageRef depth;                  // the engine's depth buffer
    VkExtent2D screen{0, 0};
    VkFormat depthStencil = VK_FORMAT_UNDEFINED;  // for the stencil textures
    // Epipolar's coordinate texture: R16G16_UNORM (NDC * 0.5 + 0.5) or R32G32_SFLOAT (NDC); the
    // shaders read and write NDC through a [0, 1] encoding either way.
    VkFormat coordinateFormat = VK_FORMAT_R32G32_SFLOAT;
};

// The light's images, each invalid where the light has none (or the chain samples none).
struct LightImages {
    rg::ImageRef shadowMap;   // the light's depth
    rg::ImageRef lightColor;  // light-space color
    rg::ImageRef table;       // point-light table; invalid for directional lights
    uint32_t shadowMapSize = 0;
};

}  // namespace ls
