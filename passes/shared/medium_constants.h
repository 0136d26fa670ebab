#pragma once
// A non-uniform medium's part of the frame constants (frame_constants_fields.h's medium,
// fogVolumes and fogDensity), with the fog volumes that cannot change the frame left out.
#include "scattering_params.h"

namespace ls {

// The volumes kept are those whose bounding sphere meets the view's frustum or, for a point or
// spot light, the hull of the frustum and the light (every path from a visible point to the
// light lies in it); volumes of density 0 are dropped too.
void writeMediumConstants(FrameConstants& f, const CameraParams& camera, const LightParams& light,
                          const MediumParams& medium);

// Whether a fog volume can change a frame of this camera and light (writeMediumConstants' test).
bool fogVolumeMatters(const FogVolumeParams& volume, const CameraParams& camera,
                      const LightParams& light);

}  // namespace ls
