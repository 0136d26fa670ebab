#pragma once
// The point-light table as a plugin-owned image that outlives frames, refilled on the GPU only when
// the medium, the light's radius or the table's scale change.
#include <array>
#include <memory>

#include "shared/shared_state.h"
#include "rendergraph/device.h"
#include "rendergraph/owned_image.h"

namespace lightscatter::detail {

class PointTable {
public:
    PointTable(const rg::Device& device, uint32_t width, uint32_t height);
    PointTable(const PointTable&) = delete;
    PointTable& operator=(const PointTable&) = delete;

    // Refills the table if what it depends on changed since the last fill (waits for the GPU).
    // Returns true when it did.
    bool update(const ls::Shared& shared);
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

}  // namespace lightscatter::detail
