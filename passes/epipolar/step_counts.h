#pragma once
// Epipolar's step counter (lightscatter::DebugOptions::countSteps): the counting variant of the ray
// march (shaders/epipolar/ray_march.frag with LS_COUNT_STEPS) adds what each invocation did into a
// storage buffer of one row of counters per slice; the plugin clears it before the marches and adds
// the rows up once the frame is done. A row's sums stay far below 2^32 at every profile, where one
// counter for the whole frame would wrap.
#include <array>
#include <cstdint>

#include "rendergraph/render_graph.h"

namespace ls {

// The counters of a row, in ray_march.frag's order (kCount*).
enum class StepCount : uint32_t {
    Samples,          // ray-marching samples marched (each once, whatever the cube faces)
    Rays,             // rays that cross the shadow map's frustum (once per cube face)
    LineSteps,        // level-0 steps along the slice's line: shadow-map look-ups
    TreeNodes,        // min/max tree nodes tested
    DegenerateRays,   // rays off their slice's line, marched on their own
    DegenerateSteps,  // ... and their look-ups
};
inline constexpr uint32_t kStepCounters = 6;
inline constexpr uint32_t kStepCountStride = 8;  // uint32 per row (ray_march.frag's kCountStride)

inline uint64_t stepCountBytes(uint32_t slices) {
    return uint64_t{slices} * kStepCountStride * sizeof(uint32_t);
}

// The rows of `slices` slices added up, indexed by StepCount.
std::array<uint64_t, kStepCounters> sumStepCounts(const uint32_t* rows, uint32_t slices);

// Zeroes the counter before the frame's marches; returns its new version.
struct ClearStepCountsInputs {
    rg::BufferRef counts;
};
rg::BufferRef addClearStepCounts(rg::RenderGraph& g, const ClearStepCountsInputs& in);

}  // namespace ls
