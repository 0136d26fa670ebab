#pragma once
// The temporal mode's jitter source: a tile of blue noise (void and cluster, Ulichney 1993), made
// on the CPU once per process and kept by the frame graph as a texture. Each froxel reads its own
// offsets from it, so neighbouring froxels sample far-apart points of their froxels in the same
// frame, and the clamp's neighbourhood (temporal.comp) spans the froxels' spread.
#include <cstdint>
#include <vector>

#include "rendergraph/persistent_store.h"
#include "rendergraph/render_graph.h"
#include "shared/shared_state.h"

namespace ls {

// The tile's side, in texels; a power of two, so that the shaders wrap with a mask.
inline constexpr uint32_t kFroxelNoiseSize = 64;

// A size x size tile of void-and-cluster ranks, row by row: texel i holds (rank + 0.5) / size^2,
// each rank once, so the values are evenly spread over (0, 1) and any window of the tile holds
// low and high values alike. `seed` picks the starting pattern; the same seed gives the same tile.
std::vector<float> voidAndClusterTile(uint32_t size, uint64_t seed);

// kFroxelNoiseSize's tile, made on first use.
const std::vector<float>& froxelBlueNoise();

rg::PersistentImageDesc froxelBlueNoiseDesc();

// The tile as a persistent R32_SFLOAT storage image, uploaded in the first frame that reads it
// (the passes of later frames record nothing).
struct FroxelBlueNoiseInputs {
    Shared shared;
    rg::HostDataRef<rg::PersistentKey> key;  // the frame's: one tile serves every light
};
rg::ImageRef addFroxelBlueNoise(rg::RenderGraph& graph, const FroxelBlueNoiseInputs& in);

}  // namespace ls
