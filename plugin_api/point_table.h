#pragma once
// The point-light table as a plugin-owned image that outlives frames, refilled on the GPU only when
// the medium, the light's radius or the table's scale change.
#include <array>
#include <memory>

#include "common/shared_state.h"
#include "rendergraph/device.h"

namespace lightscatter::detail {

class PointTable {
public:
    PointTable(const rg::Device& device, uint32_t width, uint32_t height);
    ~PointTable();
    PointTable(const PointTable&) = delete;
    PointTable& operator=(const PointTable&) = delete;

    // Refills the table if what it depends on changed since the last fill (waits for the GPU).
    // Returns true when it did.
    bool update(const ls::Shared& shared);
    VkImage image() const { return image_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    bool filled() const { return filled_; }

private:
    const rg::Device& device_;
    uint32_t width_, height_;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    bool filled_ = false;
    std::array<float, 16> key_{};
};

}  // namespace lightscatter::detail
