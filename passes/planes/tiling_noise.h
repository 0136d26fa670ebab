#pragma once
// The plugin's own tiling noise for seed 002's scrolling noise, where the engine gives none: an
// image the frame graph keeps across frames (rg::RenderGraph::persistentImage), made by the noise
// pass (addTilingNoise) in the first frame recorded that samples it.
#include "rendergraph/persistent_store.h"

namespace ls {

// Two layers of value noise, repeating.
inline constexpr VkExtent2D kNoiseExtent{256, 256};
inline constexpr VkFormat kNoiseFormat = VK_FORMAT_R8G8_UNORM;

rg::PersistentImageDesc tilingNoiseDesc();

}  // namespace ls
