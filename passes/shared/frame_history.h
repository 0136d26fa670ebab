#pragma once
// A method's state carried on the GPU from one frame to the next (froxels' temporal mode): the
// plugin keeps two images of the shape the method asks for and alternates them, each frame reading
// the one the frame before wrote and writing the other. The queue runs frames in the order they
// were recorded, and each frame's graph waits, at its start, for the earlier commands' reads and
// writes of both, so two suffice however many frames are in flight.
#include <vulkan/vulkan.h>

#include <cstdint>

#include "frame_constants.h"

namespace ls {

// What a method keeps (format UNDEFINED: nothing).
struct HistoryShape {
    VkFormat format = VK_FORMAT_UNDEFINED;
    uint32_t width = 0, height = 0, depth = 1;
    bool operator==(const HistoryShape&) const = default;
    bool given() const { return format != VK_FORMAT_UNDEFINED; }
};

// The frame's view of its history, given to each record() as host data.
struct HistoryFrame {
    // The frame before's first light's constants (its camera and the medium).
    FrameConstants previous{};
    // The history image holds the frame before's state: false for the first frame, after a reset
    // (FrameDescription::resetHistory), or when the shape or the method changed.
    bool valid = false;
    // Frames since the history began (0: this is its first), for a method's jitter sequence.
    uint32_t index = 0;
};

}  // namespace ls
