#include "tiling_noise.h"

namespace ls {

TilingNoise::TilingNoise(const rg::Device& device)
    : image_(device, kNoiseFormat, kNoiseExtent,
             VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "tiling noise") {}

}  // namespace ls
