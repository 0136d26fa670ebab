#pragma once
// Placement of transient resources in a few memory blocks, sharing memory between resources whose
// lifetimes do not overlap.
//
// Invariant (tested over every placement): two resources placed in the same block whose lifetimes
// overlap never overlap in memory; where one is linear (a buffer) and the other is not (an
// optimally tiled image), their ranges are also at least bufferImageGranularity apart, page for
// page.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "compiled_graph.h"

namespace rg {

struct PlacementItem {
    VkDeviceSize size = 0;
    VkDeviceSize alignment = 1;
    uint32_t first = 0;  // first and last pass position using it, inclusive
    uint32_t last = 0;
    uint32_t memoryType = 0;
    bool linear = false;
};

struct Placement {
    uint32_t block = 0;
    VkDeviceSize offset = 0;
};

struct PlacementResult {
    std::vector<Placement> placements;  // parallel to the items
    std::vector<MemoryBlockPlan> blocks;
};

// Best fit over lifetime x size rectangles: each item into the smallest gap left free by the
// resources alive at the same time (as AMD's Render Pipeline Shaders places its heaps), the items
// taken in a few orders (largest, largest area, longest-lived first, and by first use), keeping the
// order that needs the least memory. With aliasing off every resource gets memory of its own.
PlacementResult placeResources(const std::vector<PlacementItem>& items, VkDeviceSize granularity,
                               bool aliasing);

bool lifetimesOverlap(const PlacementItem& a, const PlacementItem& b);

// Returns an empty string when the invariant holds, else a description of the first violation.
std::string checkPlacement(const std::vector<PlacementItem>& items, const PlacementResult& result,
                           VkDeviceSize granularity);

}  // namespace rg
