#pragma once
// A light's point-light table: an image the frame graph keeps for the light across frames
// (rg::RenderGraph::persistentImage, under the light's key), filled by the table pass
// (addPointTable) in a frame whose medium, light radius or table scale differ from those of the
// frame that filled it last. Frames run on the GPU in the order they were recorded, so each finds
// the table as the frames recorded before it left it: a frame recorded ahead with another medium
// fills it for itself, and no frame waits for another.
#include <cstdint>

#include "frame_constants.h"
#include "rendergraph/persistent_store.h"
#include "scattering_params.h"

namespace ls {

// The table's size, in texels (phi x log(hEff / r0)).
inline constexpr uint32_t kTableWidth = 512;
inline constexpr uint32_t kTableHeight = 256;

// The table as the graph keeps it: sampled by fragment and compute shaders between frames.
rg::PersistentImageDesc pointTableDesc();

// What a table filled with these constants depends on (shaders/shared/point_table.comp: the
// medium, the phase, the light's radius and the table's scale), as one number: equal constants,
// equal stamps.
uint64_t pointTableStamp(const FrameConstants& constants, MiePhase phase, bool nonUniform);

}  // namespace ls
