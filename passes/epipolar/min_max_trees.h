#pragma once
// How many levels of seed 000's 1D min/max trees a shadow map gets, and whether it gets any.
#include <cstdint>

namespace ls {

// Number of min/max tree levels built for a shadow map of this size (level 1 covers 2 samples).
uint32_t treeLevels(uint32_t shadowMapSize);
// Whether min/max trees can be built: the march climbs from level 1 to level 2 and reads both the
// odd and the even texture, so a shadow map needs 4 texels or more. Smaller maps are marched
// texel by texel, which at that size costs nothing.
bool treesFit(uint32_t shadowMapSize);

}  // namespace ls
