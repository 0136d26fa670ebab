#pragma once
// Compositing where Lin is made (shaders/shared/composite_into.glsl): the pass that makes Lin
// read-modify-writes the engine's color, and the Lin output when the frame has one, so no
// screen-sized Lin texture and no pass of its own are needed. The epipolar unwarp and fix-up do
// it; the composite node does it for the methods that leave Lin in a screen texture.
#include <string>
#include <vector>

#include "rendergraph/binding_table.h"
#include "rendergraph/pass_context.h"
#include "rendergraph/pipeline.h"
#include "rendergraph/render_graph.h"
#include "shared_nodes.h"

namespace ls {

struct CompositeTarget {
    rg::ImageRef color;         // the engine's color: RGBA16F or RGBA32F, storage
    rg::ImageRef inscatterOut;  // RGBA32F; invalid: none
    bool addOnly = false;       // a frame's later light: add Lin, the first applied the extinction
};

// The pass's rows for the target's read-modify-written images (LS_BINDING_ENGINE_COLOR and, when
// there is one, LS_BINDING_LIN_OUT); returns their new versions.
CompositeOutputs addCompositeTarget(rg::BindingTable& table, const CompositeTarget& target);

}  // namespace ls
