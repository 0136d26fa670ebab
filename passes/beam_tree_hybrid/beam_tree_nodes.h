#pragma once
// Seed 004's hybrid method (5.4, `beam-tree-analytic`) as nodes: the CPU's triangles uploaded, the
// fully lit pyramids integrated in closed form, and the uncertain parts of the sampling planes
// shaded with the shadow map. What is certainly dark is never drawn.
#include "beam_tree_frame.h"
#include "shared/node_inputs.h"

namespace ls {

struct BeamTreeInputs {
    rg::BufferRef constants;
    rg::ImageRef cameraZ;     // R32F, screen
    rg::ImageRef depth;       // the engine's depth: a read-only depth attachment for the planes
    rg::ImageRef table;       // the point-light table
    rg::ImageRef shadowMap;   // invalid: the uncertain parts are not sampled (a point light)
    rg::ImageRef lightColor;  // invalid without one
};

struct BeamTreeOptions {
    uint32_t capacityPoints = 3 * 4096;  // the triangle buffer's size, in points
    bool reversedZ = false;
};

// Returns Lin (R32G32B32A32_SFLOAT, screen): exits add, entries subtract, so partial sums go
// negative.
rg::ImageRef addBeamTreeHybrid(rg::RenderGraph& graph, const Shared& shared, BeamTreeFrameRef frame,
                               const BeamTreeInputs& in, const BeamTreeOptions& options);

}  // namespace ls
