#pragma once
// FrameDescription::volumeOut: the froxel grid's layout as the header gives it (froxelVolume()),
// and the rules a frame that asks for the grid must meet once its method is known.
#include <vector>

#include <lightscatter/lightscatter.h>
#include "frame_setup.h"
#include "method_choice.h"

namespace lightscatter::detail {

// The light whose settings decide a one-per-frame method's grid: the first reaching the view (the
// chain's first), else the first of the frame.
size_t gridLight(const ValidatedFrame& frame);

// The grid of `frame` for a screen of `screen` texels (the graph's: maxRenderSize's when there is
// one).
FroxelVolume volumeLayout(const ValidatedFrame& frame, VkExtent2D screen);

// volumeOut given: the frame's method must export a volume (froxels), and the image's extent must
// be the grid's. Throws InvalidInput naming volumeOut.
void checkVolumeOut(const ImageInput& volumeOut, const ValidatedFrame& frame,
                    const std::vector<MethodChoice>& choices, VkExtent2D screen);

}  // namespace lightscatter::detail
