#pragma once
// The frame's medium, checked and put in the passes' terms (shared/scattering_params.h).
#include <lightscatter/lightscatter.h>

#include "shared/scattering_params.h"

namespace lightscatter::detail {

// Throws InvalidInput naming the field of `medium` that breaks its rule. A medium without height
// fog or volumes is homogeneous: its density is folded into the coefficients.
ls::MediumParams setupMedium(const Medium& medium);

}  // namespace lightscatter::detail
