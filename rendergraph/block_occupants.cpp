#include "block_occupants.h"

#include <algorithm>

namespace rg::detail {

BlockOccupants::BlockOccupants(const std::vector<Occupant>& occupants) {
    for (const Occupant& o : occupants) {
        points_.push_back(o.begin);
        points_.push_back(o.end);
        begins_.push_back(o.begin);
        ends_.push_back(o.end);
    }
    std::sort(points_.begin(), points_.end());
    points_.erase(std::unique(points_.begin(), points_.end()), points_.end());
    std::sort(begins_.begin(), begins_.end());
    std::sort(ends_.begin(), ends_.end());
    leaves_ = points_.size() > 1 ? points_.size() - 1 : 1;
    nodes_.assign(4 * leaves_, {});
    for (const Occupant& o : occupants) insert(1, 0, leaves_, from(o.begin), to(o.end), o);
}

std::pair<VkPipelineStageFlags2, VkAccessFlags2> BlockOccupants::meeting(VkDeviceSize begin,
                                                                         VkDeviceSize end) const {
    std::pair<VkPipelineStageFlags2, VkAccessFlags2> out{0, 0};
    if (begin < end) query(1, 0, leaves_, from(begin), to(end), out);
    return out;
}

// Those that begin before its end, less those that end at or before its beginning (which all
// began before it).
size_t BlockOccupants::count(VkDeviceSize begin, VkDeviceSize end) const {
    if (begin >= end) return 0;
    const auto startedBefore =
        std::lower_bound(begins_.begin(), begins_.end(), end) - begins_.begin();
    const auto endedBefore = std::upper_bound(ends_.begin(), ends_.end(), begin) - ends_.begin();
    return static_cast<size_t>(startedBefore - endedBefore);
}

// The elementary intervals (between consecutive end points) that [begin, end) meets are
// from(begin) up to, not including, to(end).
size_t BlockOccupants::from(VkDeviceSize begin) const {
    const auto after = std::upper_bound(points_.begin(), points_.end(), begin) - points_.begin();
    return after > 0 ? static_cast<size_t>(after - 1) : 0;
}

size_t BlockOccupants::to(VkDeviceSize end) const {
    return static_cast<size_t>(std::lower_bound(points_.begin(), points_.end(), end) -
                               points_.begin());
}

void BlockOccupants::insert(size_t node, size_t lo, size_t hi, size_t a, size_t b,
                            const Occupant& o) {
    if (b <= lo || hi <= a || a >= b) return;
    Node& n = nodes_[node];
    n.subStages |= o.stages;
    n.subAccess |= o.access;
    if (a <= lo && hi <= b) {
        n.coverStages |= o.stages;
        n.coverAccess |= o.access;
        return;
    }
    const size_t mid = (lo + hi) / 2;
    insert(2 * node, lo, mid, a, b, o);
    insert(2 * node + 1, mid, hi, a, b, o);
}

void BlockOccupants::query(size_t node, size_t lo, size_t hi, size_t a, size_t b,
                           std::pair<VkPipelineStageFlags2, VkAccessFlags2>& out) const {
    if (b <= lo || hi <= a || a >= b) return;
    const Node& n = nodes_[node];
    if (a <= lo && hi <= b) {
        out.first |= n.subStages;
        out.second |= n.subAccess;
        return;
    }
    // An occupant covering this whole node meets the part of [a, b) inside it.
    out.first |= n.coverStages;
    out.second |= n.coverAccess;
    const size_t mid = (lo + hi) / 2;
    query(2 * node, lo, mid, a, b, out);
    query(2 * node + 1, mid, hi, a, b, out);
}

}  // namespace rg::detail
