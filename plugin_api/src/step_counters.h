#pragma once
// DebugOptions::countSteps: the buffers epipolar's counting march adds into, one per frame that
// may be in flight (as the timestamp queries), so that a frame's counts wait for its report.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include <lightscatter/lightscatter.h>
#include "frame_graph.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/retire_list.h"

namespace lightscatter::detail {

class StepCounters {
  public:
    static constexpr uint64_t kFrames = Plugin::kTimedFrames;
    explicit StepCounters(const rg::Device& device) : device_(device) {}
    // The counter of frame `frame` given to the graph, for `slices` slices: a buffer too small is
    // replaced (retired after `lastFrame`).
    void import(const FrameGraph& fg, uint64_t frame, uint32_t slices, uint64_t lastFrame,
                rg::RetireList& retired);
    // What frame `frame`'s marches counted (the GPU has finished it).
    std::optional<StepCounts> read(uint64_t frame, uint32_t slices) const;

  private:
    const rg::Device& device_;
    std::array<std::unique_ptr<rg::HostBuffer>, kFrames> buffers_;
};

}  // namespace lightscatter::detail
