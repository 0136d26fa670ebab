#pragma once
// Seed 001 as a node: Lin of an unshadowed point or spot light in closed form, per pixel.
#include "shared/node_inputs.h"

namespace ls {

struct AnalyticInputs {
    rg::BufferRef constants;  // the frame's FrameConstants
    rg::ImageRef depth;       // the engine's depth: where each pixel's ray ends
};

// Returns Lin (R16G16B16A16_SFLOAT, screen).
rg::ImageRef addAnalytic(rg::RenderGraph& graph, const Shared& shared, const AnalyticInputs& in);

}  // namespace ls
