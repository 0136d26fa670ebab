#include "step_counters.h"

namespace lightscatter::detail {

void StepCounters::import(const FrameGraph& fg, uint64_t frame, uint64_t bytes, uint64_t lastFrame,
                          rg::RetireList& retired) {
    if (!fg.stepCounts.valid()) return;
    auto& buffer = buffers_[frame % kFrames];
    const rg::ImportedBuffer d = stepCountImport(VK_NULL_HANDLE, bytes);
    if (buffer && buffer->size() < d.size)
        retired.retire(lastFrame, [old = std::shared_ptr<rg::HostBuffer>(std::move(buffer))] {});
    if (!buffer)
        buffer =
            std::make_unique<rg::HostBuffer>(device_, d.size, d.usage, "ray-march step counts");
    fg.graph->updateImport(fg.stepCounts, stepCountImport(buffer->buffer(), bytes));
}

std::optional<StepCounts> StepCounters::read(uint64_t frame, uint64_t bytes,
                                             const ls::MethodUnit& counter) const {
    const auto& buffer = buffers_[frame % kFrames];
    if (!buffer) return std::nullopt;
    StepCounts s;
    counter.readStepCounts(buffer->data(), bytes, s);
    return s;
}

}  // namespace lightscatter::detail
