#pragma once
// A light's point-light table: a plugin-owned image that outlives frames, filled by the frame
// graph's table pass (addPointTable) in a frame whose medium, light radius or table scale differ
// from those of the frame that filled it last. Frames run on the GPU in the order they were
// recorded, so each finds the table as the frames recorded before it left it: a frame recorded
// ahead with another medium fills it for itself, and no frame waits for another.
#include <array>

#include "frame_constants.h"
#include "rendergraph/device.h"
#include "rendergraph/owned_image.h"
#include "scattering_params.h"

namespace ls {

// The table's size, in texels (phi x log(hEff / r0)).
inline constexpr uint32_t kTableWidth = 512;
inline constexpr uint32_t kTableHeight = 256;

class PointTable {
  public:
    PointTable(const rg::Device& device, uint32_t width, uint32_t height);
    PointTable(const PointTable&) = delete;
    PointTable& operator=(const PointTable&) = delete;

    // Whether a frame with these constants must fill the table before reading it.
    bool needsFill(const FrameConstants& constants, MiePhase phase) const;
    // A frame that fills the table was recorded: the frames recorded after it find it filled.
    void recordedFill(const FrameConstants& constants, MiePhase phase);
    // Some recorded frame filled it: a frame finds it in SHADER_READ_ONLY_OPTIMAL (else its
    // contents are undefined, UNDEFINED).
    bool filled() const { return filled_; }
    VkImage image() const { return image_.image(); }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }

  private:
    using Key = std::array<float, 16>;
    static Key keyOf(const FrameConstants& c, MiePhase phase);

    uint32_t width_, height_;
    rg::OwnedImage image_;
    bool filled_ = false;
    Key key_{};
};

}  // namespace ls
