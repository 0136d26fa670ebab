#pragma once
// An engine-owned image with its own memory: the host's depth, HDR color, shadow map and Lin
// output, which it hands to the plugin each frame.
#include "rendergraph/owned_image.h"

namespace host {

using GpuImage = rg::OwnedImage;

}  // namespace host
