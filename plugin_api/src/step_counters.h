#pragma once
// DebugOptions::countSteps: the buffers a counting chain adds into (MethodUnit::stepCountBytes),
// one per frame that may be in flight (as the timestamp queries), so that a frame's counts wait for
// its report. The method that counted reads them (MethodUnit::readStepCounts).
#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include <lightscatter/lightscatter.h>
#include "frame_graph.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/retire_list.h"
#include "shared/method_unit.h"

namespace lightscatter::detail {

class StepCounters {
  public:
    static constexpr uint64_t kFrames = Plugin::kTimedFrames;
    explicit StepCounters(const rg::Device& device) : device_(device) {}
    // The counter of frame `frame` given to the graph, of `bytes`: a buffer too small is replaced
    // (retired after `lastFrame`).
    void import(const FrameGraph& fg, uint64_t frame, uint64_t bytes, uint64_t lastFrame,
                rg::RetireList& retired);
    // What frame `frame`'s chains counted into `bytes` of it, read by `counter`, the method that
    // counted (the GPU has finished the frame).
    std::optional<StepCounts> read(uint64_t frame, uint64_t bytes,
                                   const ls::MethodUnit& counter) const;

  private:
    const rg::Device& device_;
    std::array<std::unique_ptr<rg::HostBuffer>, kFrames> buffers_;
};

}  // namespace lightscatter::detail
