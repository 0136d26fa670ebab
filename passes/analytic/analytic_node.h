#pragma once
// Seed 001 as a node: Lin of an unshadowed point or spot light in closed form, per pixel.
#include "shared/chain_context.h"

namespace ls {

struct AnalyticInputs {
    ChainContext chain;  // its constants, and the depth: where each pixel's ray ends
};

// Returns Lin (R16G16B16A16_SFLOAT, screen).
rg::ImageRef addAnalytic(rg::RenderGraph& graph, const AnalyticInputs& in);

}  // namespace ls
