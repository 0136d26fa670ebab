#include "epipolar_nodes.h"
#include "rendergraph/pass_context.h"

namespace ls {

// Only the count is zeroed: the refinement writes the entries below it, and the passes read no
// others.
rg::BufferRef addClearMarchList(rg::RenderGraph& g, const EpipolarSizes& s) {
    const uint64_t bytes = sizeof(uint32_t) * (1 + uint64_t{s.marchListCapacity()});
    const rg::BufferRef list = g.createBuffer("ray-march list", rg::BufferDesc{bytes});
    auto pass = g.addPass("clear ray-march list", rg::PassType::Transfer);
    const rg::BufferRef cleared = pass.transferDst(list);
    pass.execute([cleared](rg::PassContext& ctx) {
        ctx.vk().CmdFillBuffer(ctx.cmd(), ctx.buffer(cleared), 0, sizeof(uint32_t), 0u);
    });
    return cleared;
}

}  // namespace ls
