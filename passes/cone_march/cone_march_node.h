#pragma once
// Seed 003 as a node: a fixed number of samples per pixel along the part of its ray the light can
// reach (the spot's cone within its range), or along the whole ray (the seed's naive baseline).
#include "cone_march_options.h"
#include "shared/chain_context.h"

namespace ls {

struct ConeMarchInputs {
    ChainContext chain;  // its constants, and the depth: where each pixel's ray ends
    // light.shadowMap invalid: no shadow sampling (the low-end mode); light.lightColor invalid
    // without one. The table is not read.
    LightImages light;
};

// Returns Lin (R16G16B16A16_SFLOAT, screen).
rg::ImageRef addConeMarch(rg::RenderGraph& graph, const ConeMarchInputs& in,
                          const ConeMarchOptions& options);

}  // namespace ls
