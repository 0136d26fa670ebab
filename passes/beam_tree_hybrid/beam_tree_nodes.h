#pragma once
// Seed 004's two methods as nodes. Both upload the CPU's triangles and never draw what the beam
// tree says is certainly dark. `beam-tree-analytic` (5.4) integrates the fully lit pyramids in
// closed form and samples only the uncertain parts of the planes, with the shadow map;
// `beam-tree-sampling` (5.3) samples the lit parts of the planes without shadow look-ups and the
// uncertain parts with them.
#include "beam_tree_frame.h"
#include "shared/node_inputs.h"

namespace ls {

struct BeamTreeInputs {
    rg::BufferRef constants;
    rg::ImageRef depth;       // the engine's depth: where each pixel's ray ends, and a read-only
                              // depth attachment for the planes
    rg::ImageRef table;       // the point-light table
    rg::ImageRef shadowMap;   // invalid: the uncertain parts are not sampled (a point light)
    rg::ImageRef lightColor;  // invalid without one
};

struct BeamTreeSamplingInputs {
    rg::BufferRef constants;
    rg::ImageRef depth;       // the engine's depth: a read-only depth attachment for the planes
    rg::ImageRef shadowMap;   // invalid: the uncertain parts are sampled as lit (a point light)
    rg::ImageRef lightColor;  // invalid without one
};

struct BeamTreeOptions {
    // The triangle buffer's size, in points: at least the frame's (BeamTreeFrame::points). The
    // plugin starts at 3 * 4096 and doubles it (a graph rebuild) when a frame needs more.
    uint32_t capacityPoints = 3 * 4096;
    bool reversedZ = false;
};

// Returns Lin (R32G32B32A32_SFLOAT, screen): exits add, entries subtract, so partial sums go
// negative. `frame` was built with LitSpace::ClosedForm.
rg::ImageRef addBeamTreeHybrid(rg::RenderGraph& graph, const Shared& shared, BeamTreeFrameRef frame,
                               const BeamTreeInputs& in, const BeamTreeOptions& options);

// Returns Lin (R32G32B32A32_SFLOAT, screen). `frame` was built with LitSpace::Planes.
rg::ImageRef addBeamTreeSampling(rg::RenderGraph& graph, const Shared& shared,
                                 BeamTreeFrameRef frame, const BeamTreeSamplingInputs& in,
                                 const BeamTreeOptions& options);

}  // namespace ls
