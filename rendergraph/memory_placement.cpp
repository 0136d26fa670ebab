#include "memory_placement.h"

#include <algorithm>
#include <functional>
#include <numeric>
#include <string>

namespace rg {
namespace {

VkDeviceSize alignUp(VkDeviceSize v, VkDeviceSize a) {
    return a <= 1 ? v : (v + a - 1) / a * a;
}
VkDeviceSize alignDown(VkDeviceSize v, VkDeviceSize a) {
    return a <= 1 ? v : v / a * a;
}

struct Range {
    VkDeviceSize begin;
    VkDeviceSize end;
};

// The memory a placed neighbour keeps from `item`: its own range, widened to whole granularity
// pages when the two differ in tiling.
Range blockedRange(const PlacementItem& neighbour, VkDeviceSize offset, const PlacementItem& item,
                   VkDeviceSize granularity) {
    Range r{offset, offset + neighbour.size};
    if (neighbour.linear != item.linear) {
        r.begin = alignDown(r.begin, granularity);
        r.end = alignUp(r.end, granularity);
    }
    return r;
}

}  // namespace

bool lifetimesOverlap(const PlacementItem& a, const PlacementItem& b) {
    return a.first <= b.last && b.first <= a.last;
}

namespace {

// Places the items in `order`, each at the best fit among the gaps the already placed ones leave
// while it is alive.
PlacementResult placeInOrder(const std::vector<PlacementItem>& items,
                             const std::vector<uint32_t>& order, VkDeviceSize granularity,
                             bool aliasing) {
    PlacementResult result;
    result.placements.resize(items.size());
    std::vector<uint32_t> blockOfType;  // memory type -> block index (one block per type)
    auto blockFor = [&](uint32_t memoryType) {
        if (memoryType >= blockOfType.size()) blockOfType.resize(memoryType + 1, kInvalidIndex);
        if (blockOfType[memoryType] == kInvalidIndex) {
            blockOfType[memoryType] = static_cast<uint32_t>(result.blocks.size());
            result.blocks.push_back({memoryType, 0});
        }
        return blockOfType[memoryType];
    };

    // The placed items alive at each pass position, so that an item meets only those it lives
    // beside: a graph of many short chains (a light each) places in time linear in its resources,
    // not quadratic (issue #22: `budget --lights` of 3,000 lights took 26 s). Without aliasing
    // every placed item is busy.
    uint32_t positions = 0;
    for (const PlacementItem& item : items) positions = std::max(positions, item.last + 1);
    std::vector<std::vector<uint32_t>> aliveAt(aliasing ? positions : 0);
    std::vector<uint32_t> placed, seenAt(items.size(), ~0u);
    for (uint32_t i : order) {
        const PlacementItem& item = items[i];
        const uint32_t block = blockFor(item.memoryType);
        std::vector<Range> busy;
        auto meet = [&](uint32_t j) {
            if (result.placements[j].block != block) return;
            busy.push_back(blockedRange(items[j], result.placements[j].offset, item, granularity));
        };
        if (aliasing) {
            for (uint32_t t = item.first; t <= item.last; ++t)
                for (uint32_t j : aliveAt[t])
                    if (seenAt[j] != i) {
                        seenAt[j] = i;
                        meet(j);
                    }
        } else {
            for (uint32_t j : placed) meet(j);
        }
        std::sort(busy.begin(), busy.end(),
                  [](const Range& a, const Range& b) { return a.begin < b.begin; });

        // Walk the gaps between busy ranges; keep the tightest one the item fits in.
        VkDeviceSize cursor = 0;
        VkDeviceSize bestOffset = 0, bestSlack = ~VkDeviceSize{0};
        bool found = false;
        for (const Range& r : busy) {
            const VkDeviceSize start = alignUp(cursor, item.alignment);
            if (r.begin > start && r.begin - start >= item.size) {
                const VkDeviceSize slack = r.begin - start - item.size;
                if (slack < bestSlack) {
                    bestSlack = slack;
                    bestOffset = start;
                    found = true;
                }
            }
            cursor = std::max(cursor, r.end);
        }
        if (!found) bestOffset = alignUp(cursor, item.alignment);

        result.placements[i] = {block, bestOffset};
        result.blocks[block].size = std::max(result.blocks[block].size, bestOffset + item.size);
        placed.push_back(i);
        if (aliasing)
            for (uint32_t t = item.first; t <= item.last; ++t) aliveAt[t].push_back(i);
    }
    return result;
}

VkDeviceSize totalSize(const PlacementResult& r) {
    VkDeviceSize total = 0;
    for (const auto& b : r.blocks) total += b.size;
    return total;
}

}  // namespace

PlacementResult placeResources(const std::vector<PlacementItem>& items, VkDeviceSize granularity,
                               bool aliasing) {
    // Best fit depends on the order the items go in, and no one order wins on every graph (largest
    // first leaves gaps a long-lived middle-sized item cannot use): try a few, keep the smallest.
    const auto length = [&](uint32_t i) {
        return VkDeviceSize{items[i].last - items[i].first + 1};
    };
    using Key = std::function<bool(uint32_t, uint32_t)>;
    const Key orders[] = {
        [&](uint32_t a, uint32_t b) { return items[a].size > items[b].size; },
        [&](uint32_t a, uint32_t b) {
            return items[a].size * length(a) > items[b].size * length(b);
        },
        [&](uint32_t a, uint32_t b) {
            return length(a) != length(b) ? length(a) > length(b) : items[a].size > items[b].size;
        },
        [&](uint32_t a, uint32_t b) {
            return items[a].first != items[b].first ? items[a].first < items[b].first
                                                    : items[a].size > items[b].size;
        },
    };
    PlacementResult best;
    bool any = false;
    for (const Key& before : orders) {
        std::vector<uint32_t> order(items.size());
        std::iota(order.begin(), order.end(), 0u);
        std::stable_sort(order.begin(), order.end(), before);
        PlacementResult r = placeInOrder(items, order, granularity, aliasing);
        if (!any || totalSize(r) < totalSize(best)) best = std::move(r);
        any = true;
        if (!aliasing) break;  // every order gives the same sum
    }
    return best;
}

std::string checkPlacement(const std::vector<PlacementItem>& items, const PlacementResult& result,
                           VkDeviceSize granularity) {
    for (size_t a = 0; a < items.size(); ++a) {
        const auto& pa = result.placements[a];
        if (pa.offset % std::max<VkDeviceSize>(items[a].alignment, 1) != 0)
            return "item " + std::to_string(a) + " is misaligned";
        if (pa.offset + items[a].size > result.blocks.at(pa.block).size)
            return "item " + std::to_string(a) + " ends beyond its block";
        for (size_t b = a + 1; b < items.size(); ++b) {
            const auto& pb = result.placements[b];
            if (pa.block != pb.block || !lifetimesOverlap(items[a], items[b])) continue;
            const Range rb = blockedRange(items[b], pb.offset, items[a], granularity);
            const Range ra{pa.offset, pa.offset + items[a].size};
            if (ra.begin < rb.end && rb.begin < ra.end)
                return "items " + std::to_string(a) + " and " + std::to_string(b) +
                       " are alive together and overlap in memory";
        }
    }
    return {};
}

}  // namespace rg
