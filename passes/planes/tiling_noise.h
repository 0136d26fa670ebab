#pragma once
// The plugin's own tiling noise for seed 002's scrolling noise: a plugin-owned image that outlives
// frames, made on the GPU the first time a frame asks for noise without an engine image.
#include "rendergraph/device.h"
#include "rendergraph/owned_image.h"
#include "shared/shared_state.h"

namespace ls {

// The plugin's own tiling noise: two layers of value noise, repeating.
inline constexpr VkExtent2D kNoiseExtent{256, 256};
inline constexpr VkFormat kNoiseFormat = VK_FORMAT_R8G8_UNORM;

class TilingNoise {
  public:
    explicit TilingNoise(const rg::Device& device);
    TilingNoise(const TilingNoise&) = delete;
    TilingNoise& operator=(const TilingNoise&) = delete;

    // Makes the noise if it has not been made (waits for the GPU). Returns true when it did.
    bool ensure(const Shared& shared);
    VkImage image() const { return image_.image(); }

  private:
    const rg::Device& device_;
    rg::OwnedImage image_;
    bool made_ = false;
};

}  // namespace ls
