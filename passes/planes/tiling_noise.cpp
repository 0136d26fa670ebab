#include "tiling_noise.h"

namespace ls {

rg::PersistentImageDesc tilingNoiseDesc() {
    rg::PersistentImageDesc d;
    d.format = kNoiseFormat;
    d.extent = kNoiseExtent;
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
    return d;
}

}  // namespace ls
