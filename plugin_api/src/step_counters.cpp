#include "step_counters.h"

#include "epipolar/step_counts.h"

namespace lightscatter::detail {

void StepCounters::import(const FrameGraph& fg, uint64_t frame, uint32_t slices, uint64_t lastFrame,
                          rg::RetireList& retired) {
    if (!fg.stepCounts.valid()) return;
    auto& buffer = buffers_[frame % kFrames];
    const rg::ImportedBuffer d = stepCountImport(VK_NULL_HANDLE, slices);
    if (buffer && buffer->size() < d.size)
        retired.retire(lastFrame, [old = std::shared_ptr<rg::HostBuffer>(std::move(buffer))] {});
    if (!buffer)
        buffer =
            std::make_unique<rg::HostBuffer>(device_, d.size, d.usage, "ray-march step counts");
    fg.graph->updateImport(fg.stepCounts, stepCountImport(buffer->buffer(), slices));
}

std::optional<StepCounts> StepCounters::read(uint64_t frame, uint32_t slices) const {
    const auto& buffer = buffers_[frame % kFrames];
    if (!buffer) return std::nullopt;
    const auto sum = ls::sumStepCounts(static_cast<const uint32_t*>(buffer->data()), slices);
    auto at = [&](ls::StepCount k) { return sum[static_cast<uint32_t>(k)]; };
    StepCounts s;
    s.samples = at(ls::StepCount::Samples);
    s.rays = at(ls::StepCount::Rays);
    s.lineSteps = at(ls::StepCount::LineSteps);
    s.treeNodes = at(ls::StepCount::TreeNodes);
    s.degenerateRays = at(ls::StepCount::DegenerateRays);
    s.degenerateSteps = at(ls::StepCount::DegenerateSteps);
    return s;
}

}  // namespace lightscatter::detail
