#include "step_counts.h"

#include "rendergraph/pass_context.h"

namespace ls {

std::array<uint64_t, kStepCounters> sumStepCounts(const uint32_t* rows, uint32_t slices) {
    std::array<uint64_t, kStepCounters> sum{};
    for (uint32_t s = 0; s < slices; ++s)
        for (uint32_t k = 0; k < kStepCounters; ++k) sum[k] += rows[s * kStepCountStride + k];
    return sum;
}

rg::BufferRef addClearStepCounts(rg::RenderGraph& g, const ClearStepCountsInputs& in) {
    auto pass = g.addPass("clear step counts", rg::PassType::Transfer);
    const rg::BufferRef cleared = pass.transferDst(in.counts);
    pass.execute([cleared](rg::PassContext& ctx) {
        ctx.vk().CmdFillBuffer(ctx.cmd(), ctx.buffer(cleared), 0, VK_WHOLE_SIZE, 0u);
    });
    return cleared;
}

}  // namespace ls
