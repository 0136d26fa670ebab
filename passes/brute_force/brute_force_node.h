#pragma once
// Brute force: every pixel marches its own ray through the shadow map, one step per texel. The
// on-GPU reference the other methods are compared with.
#include "shared/chain_context.h"

namespace ls {

struct BruteForceInputs {
    ChainContext chain;  // its constants and depth
    LightImages light;   // marched: the shadow map, and the table and light color where given
};

// Lin (R16G16B16A16_SFLOAT, screen).
rg::ImageRef addBruteForce(rg::RenderGraph& graph, const BruteForceInputs& in);

}  // namespace ls
