#pragma once
// Seed 004's two methods as nodes. Both upload the CPU's triangles and never draw what the beam
// tree says is certainly dark. `beam-tree-analytic` (5.4) integrates the fully lit pyramids in
// closed form and samples only the uncertain parts of the planes, with the shadow map;
// `beam-tree-sampling` (5.3) samples the lit parts of the planes without shadow look-ups and the
// uncertain parts with them.
#include "beam_tree_frame.h"
#include "shared/chain_context.h"

namespace ls {

// This frame's beam tree and triangles (the methods' LightData), built on the CPU before each frame
// is recorded; the nodes upload them from the frame's LightFrame when they record.
struct BeamTreeData final : LightData {
    BeamTreeFrame frame;
};
const BeamTreeFrame& beamTreeOf(const LightFrame& frame);

struct BeamTreeInputs {
    // Its constants, and the depth: where each pixel's ray ends, and a read-only depth attachment
    // for the planes.
    ChainContext chain;
    // The point-light table (the lit pyramids'); the shadow map, invalid: the uncertain parts are
    // sampled as lit (a point light); the light color, invalid without one.
    LightImages light;  // its beam tree is built with LitSpace::ClosedForm
};

struct BeamTreeSamplingInputs {
    ChainContext chain;  // its constants, and the depth: a read-only depth attachment for planes
    // The shadow map, invalid: the uncertain parts are sampled as lit (a point light); the light
    // color, invalid without one. The table is not read.
    LightImages light;  // its beam tree is built with LitSpace::Planes
};

struct BeamTreeOptions {
    // The triangle buffer's size, in points: at least the frame's (BeamTreeFrame::points). The
    // plugin starts at 3 * 4096 and doubles it (a graph rebuild) when a frame needs more.
    uint32_t capacityPoints = 3 * 4096;
    bool reversedZ = false;
};

// Returns Lin (R32G32B32A32_SFLOAT, screen): exits add, entries subtract, so partial sums go
// negative.
rg::ImageRef addBeamTreeHybrid(rg::RenderGraph& graph, const BeamTreeInputs& in,
                               const BeamTreeOptions& options);

// Returns Lin (R32G32B32A32_SFLOAT, screen).
rg::ImageRef addBeamTreeSampling(rg::RenderGraph& graph, const BeamTreeSamplingInputs& in,
                                 const BeamTreeOptions& options);

}  // namespace ls
