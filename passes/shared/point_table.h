#pragma once
// The point-light table as a plugin-owned image that outlives frames, refilled on the GPU only when
// the medium, the light's radius or the table's scale change.
#include <array>
#include <memory>

#include "rendergraph/device.h"
#include "rendergraph/owned_image.h"
#include "shared_state.h"

namespace ls {

// The table's size, in texels (phi x log(hEff / r0)).
inline constexpr uint32_t kTableWidth = 512;
inline constexpr uint32_t kTableHeight = 256;

class PointTable {
  public:
    PointTable(const rg::Device& device, uint32_t width, uint32_t height);
    PointTable(const PointTable&) = delete;
    PointTable& operator=(const PointTable&) = delete;

    // Refills the table if what it depends on changed since the last fill (waits for the GPU).
    // Returns true when it did.
    bool update(const Shared& shared);
    VkImage image() const { return image_.image(); }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    bool filled() const { return filled_; }

  private:
    const rg::Device& device_;
    uint32_t width_, height_;
    rg::OwnedImage image_;
    bool filled_ = false;
    std::array<float, 16> key_{};
};

}  // namespace ls
