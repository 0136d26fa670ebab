// Builds without Embree (CMake found no libembree-dev): every query takes the double BVH.
#include "embree_occlusion.h"

namespace host::reference {

std::shared_ptr<const EmbreeOcclusion> makeEmbreeOcclusion(const std::vector<Triangle>&, double) {
    return nullptr;
}

}  // namespace host::reference
