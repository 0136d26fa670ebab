#include "clear_counters_node.h"

#include "rendergraph/pass_context.h"

namespace ls {

rg::BufferRef addClearCounters(rg::RenderGraph& g, const ClearCountersInputs& in) {
    auto pass = g.addPass("clear step counts", rg::PassType::Transfer);
    const rg::BufferRef cleared = pass.transferDst(in.counts);
    pass.execute([cleared](rg::PassContext& ctx) {
        ctx.vk().CmdFillBuffer(ctx.cmd(), ctx.buffer(cleared), 0, VK_WHOLE_SIZE, 0u);
    });
    return cleared;
}

}  // namespace ls
