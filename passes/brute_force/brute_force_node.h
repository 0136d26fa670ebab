#pragma once
// Brute force: every pixel marches its own ray through the shadow map, one step per texel. The
// on-GPU reference the other methods are compared with.
#include "shared/node_inputs.h"

namespace ls {

// Lin (R16G16B16A16_SFLOAT, screen).
rg::ImageRef addBruteForce(rg::RenderGraph& graph, const NodeInputs& in);

}  // namespace ls
