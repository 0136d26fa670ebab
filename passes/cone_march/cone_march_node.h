#pragma once
// Seed 003 as a node: a fixed number of samples per pixel along the part of its ray the light can
// reach (the spot's cone within its range), or along the whole ray (the seed's naive baseline).
#include "shared/node_inputs.h"

namespace ls {

struct ConeMarchInputs {
    rg::BufferRef constants;  // the frame's FrameConstants
    rg::ImageRef depth;       // the engine's depth: where each pixel's ray ends
    rg::ImageRef shadowMap;   // the light's depth; invalid: no shadow sampling (the low-end mode)
    rg::ImageRef lightColor;  // light-space color; invalid without one
};

// Returns Lin (R16G16B16A16_SFLOAT, screen).
rg::ImageRef addConeMarch(rg::RenderGraph& graph, const Shared& shared, const ConeMarchInputs& in,
                          const ConeMarchOptions& options);

}  // namespace ls
