#pragma once
// What one light's passes read when they are recorded, for one frame: its constants, the method's
// CPU work, and whether its point-light table is filled this frame. The plugin gives it to each
// record() as host data (rg::HostDataRef<LightFrame>, declared by the frame graph), so a graph kept
// across frames, or frames recorded ahead, never read values someone changed since.
#include <vulkan/vulkan.h>

#include "frame_constants.h"

namespace ls {

// A method's state of one light kept across frames (the slice placement, the beam tree), filled
// by MethodUnit::prepare() before each frame is recorded; the chain's passes read it when they
// record, through LightFrame::data of the frame being recorded (never a pointer captured when the
// graph was built: a kept graph outlives the data of a method used in between).
struct LightData {
    virtual ~LightData() = default;
};

struct LightFrame {
    FrameConstants constants{};
    const LightData* data = nullptr;  // the method's prepare() of this frame (null: none)
    // The pixels whose rays may cross the light's volume this frame (lightScreenRect): the
    // per-pixel marches draw only there.
    VkRect2D screenRect{{0, 0}, {0, 0}};
};

}  // namespace ls
