#include "shared_nodes.h"

namespace ls {

rg::BufferRef addUploadConstants(rg::RenderGraph& graph, const UploadConstantsInputs& in) {
    rg::BufferRef buffer = graph.createBuffer("frame constants", {sizeof(FrameConstants)});
    auto pass = graph.addPass("upload frame constants", rg::PassType::Transfer);
    buffer = pass.transferDst(buffer);
    pass.execute([values = in.values, buffer](rg::PassContext& ctx) {
        ctx.vk().CmdUpdateBuffer(ctx.cmd(), ctx.buffer(buffer), 0, sizeof(FrameConstants),
                                 &ctx.data(values).constants);
    });
    return buffer;
}

}  // namespace ls
