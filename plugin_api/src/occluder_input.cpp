#include "occluder_input.h"

#include "beam_tree/occluder_checks.h"
#include "field_checks.h"

namespace lightscatter::detail {
namespace {

glm::vec3 vec3(const Vec3& v) {
    return {v[0], v[1], v[2]};
}

ls::beam::GivenBox given(const OccluderBox& b) {
    return {
        vec3(b.center), {vec3(b.axes[0]), vec3(b.axes[1]), vec3(b.axes[2])}, vec3(b.halfExtents)};
}

}  // namespace

std::vector<ls::beam::Occluder> beamOccluders(const std::vector<Occluder>& occluders) {
    std::vector<ls::beam::GivenOccluder> boxes;
    boxes.reserve(occluders.size());
    for (const Occluder& o : occluders)
        boxes.push_back({given(o.outer), o.inner ? std::optional(given(*o.inner)) : std::nullopt});
    const std::string refusal = ls::beam::refuseOccluders(boxes, kMaxOccluders, limits::kMaxLength);
    if (!refusal.empty()) fail(refusal);
    return ls::beam::toOccluders(boxes);
}

}  // namespace lightscatter::detail
