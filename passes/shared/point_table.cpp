#include "point_table.h"

namespace ls {

PointTable::PointTable(const rg::Device& device, uint32_t width, uint32_t height)
    : width_(width),
      height_(height),
      image_(device, VK_FORMAT_R32G32B32A32_SFLOAT, {width, height},
             VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "point-light table") {}

// What the table depends on (shaders/shared/point_table.comp): the medium, the phase, the light's
// radius and the table's scale.
PointTable::Key PointTable::keyOf(const FrameConstants& c, MiePhase phase) {
    return {c.betaR.x,
            c.betaR.y,
            c.betaR.z,
            c.betaR.w /* g */,
            c.betaM.x,
            c.betaM.y,
            c.betaM.z,
            c.betaT.x,
            c.betaT.y,
            c.betaT.z,
            c.betaT.w /* r0 */,
            c.lutInfo.x,
            c.lutInfo.y,
            c.lutInfo.z,
            static_cast<float>(phase),
            0.0f};
}

bool PointTable::needsFill(const FrameConstants& constants, MiePhase phase) const {
    return !filled_ || keyOf(constants, phase) != key_;
}

void PointTable::recordedFill(const FrameConstants& constants, MiePhase phase) {
    key_ = keyOf(constants, phase);
    filled_ = true;
}

}  // namespace ls
