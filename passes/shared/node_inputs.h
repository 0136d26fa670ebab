#pragma once
// What every scattering node may read, prepared by the plugin for one frame graph: the shared
// state, the frame's constants and the engine's images. No node writes any of it; the textures the
// nodes make are returned by the nodes that write them and passed to the nodes that read them.
#include <vulkan/vulkan.h>

#include "rendergraph/render_graph.h"
#include "shared_state.h"

namespace ls {

struct NodeInputs {
    Shared shared;
    rg::BufferRef constants;  // this frame's FrameConstants, uploaded by the first pass
    rg::ImageRef depth;       // the engine's depth buffer
    rg::ImageRef shadowMap;   // the light's depth; invalid without one
    rg::ImageRef lightColor;  // light-space color; invalid without one
    rg::ImageRef table;       // point-light table; invalid for directional lights
    VkExtent2D screen{0, 0};
    VkFormat depthStencil = VK_FORMAT_UNDEFINED;  // for the stencil textures
    // Epipolar's coordinate texture: R16G16_UNORM (NDC * 0.5 + 0.5) or R32G32_SFLOAT (NDC); the
    // shaders read and write NDC through a [0, 1] encoding either way.
    VkFormat coordinateFormat = VK_FORMAT_R32G32_SFLOAT;
    uint32_t shadowMapSize = 0;
};

}  // namespace ls
