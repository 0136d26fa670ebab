#pragma once
// What a method that carries state from one frame to the next reads besides its history images
// (rg::RenderGraph::historyImages, which the graph keeps and swaps): the frame before's constants,
// to reproject what it left (froxels' temporal mode). The plugin gives them to each record().
#include "frame_constants.h"

namespace ls {

struct PreviousFrame {
    // The frame before's first light's constants (its camera and the medium); meaningful where
    // the history is valid (rg::PassContext::history).
    FrameConstants constants{};
};

}  // namespace ls
