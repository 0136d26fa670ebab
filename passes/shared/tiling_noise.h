#pragma once
// The plugin's own tiling noise for seed 002's scrolling noise (a method that readsNoise), where
// the engine gives none: an image the frame graph keeps across frames
// (rg::RenderGraph::persistentImage), made by the noise pass in the first frame recorded that
// samples it.
#include "rendergraph/persistent_store.h"
#include "rendergraph/render_graph.h"
#include "shared_state.h"

namespace ls {

// Two layers of value noise, repeating.
inline constexpr VkExtent2D kNoiseExtent{256, 256};
inline constexpr VkFormat kNoiseFormat = VK_FORMAT_R8G8_UNORM;

rg::PersistentImageDesc tilingNoiseDesc();

// Fills the noise (R8G8_UNORM, storage) with two layers of tiling value noise in the first frame
// that samples the plugin's own; the others record nothing.
struct TilingNoiseInputs {
    Shared shared;
    rg::HostDataRef<rg::PersistentKey> key;  // the graph keeps the noise under it
};
rg::ImageRef addTilingNoise(rg::RenderGraph& graph, const TilingNoiseInputs& in);

}  // namespace ls
