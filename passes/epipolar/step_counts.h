#pragma once
// Epipolar's step counter (lightscatter::DebugOptions::countSteps): the counting variant of the ray
// march (shaders/epipolar/ray_march.frag with LS_COUNT_STEPS) adds what each invocation did into a
// storage buffer of one row of counters per slice; the plugin clears it before the marches and adds
// the rows up once the frame is done. A row's sums stay far below 2^32 at every profile, where one
// counter for the whole frame would wrap.
#include <array>
#include <cstdint>

#include "rendergraph/render_graph.h"
#include "shaders/epipolar/step_counts_layout.h"

namespace ls {

// The counters of a row (shaders/epipolar/step_counts_layout.h, which ray_march.frag adds into).
enum class StepCount : uint32_t {
    Samples = LS_COUNT_SAMPLES,
    Rays = LS_COUNT_RAYS,
    LineSteps = LS_COUNT_LINE_STEPS,
    TreeNodes = LS_COUNT_TREE_NODES,
    DegenerateRays = LS_COUNT_DEGENERATE_RAYS,
    DegenerateSteps = LS_COUNT_DEGENERATE_STEPS,
    Listed = LS_COUNT_LISTED,
    UnbuiltTreeNodes = LS_COUNT_UNBUILT_NODES,
};
inline constexpr uint32_t kStepCounters = LS_COUNTERS;
inline constexpr uint32_t kStepCountStride = LS_COUNT_STRIDE;  // uint32 per row

inline uint64_t stepCountBytes(uint32_t slices) {
    return uint64_t{slices} * kStepCountStride * sizeof(uint32_t);
}

// The rows of `slices` slices added up, indexed by StepCount.
std::array<uint64_t, kStepCounters> sumStepCounts(const uint32_t* rows, uint32_t slices);

}  // namespace ls
