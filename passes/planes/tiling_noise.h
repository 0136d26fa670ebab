#pragma once
// The plugin's own tiling noise for seed 002's scrolling noise: a plugin-owned image that outlives
// frames, made by the frame graph's noise pass (addTilingNoise) in the first frame recorded that
// samples it.
#include "rendergraph/device.h"
#include "rendergraph/owned_image.h"

namespace ls {

// The plugin's own tiling noise: two layers of value noise, repeating.
inline constexpr VkExtent2D kNoiseExtent{256, 256};
inline constexpr VkFormat kNoiseFormat = VK_FORMAT_R8G8_UNORM;

class TilingNoise {
  public:
    explicit TilingNoise(const rg::Device& device);
    TilingNoise(const TilingNoise&) = delete;
    TilingNoise& operator=(const TilingNoise&) = delete;

    // A frame that makes the noise was recorded: the frames recorded after it find it made, in
    // SHADER_READ_ONLY_OPTIMAL (before, its contents are undefined, UNDEFINED).
    void recordedMake() { made_ = true; }
    bool made() const { return made_; }
    VkImage image() const { return image_.image(); }

  private:
    rg::OwnedImage image_;
    bool made_ = false;
};

}  // namespace ls
