#include "epipolar_nodes.h"

namespace ls {

EpipolarContext addUploadEpipolarConstants(rg::RenderGraph& g,
                                           const UploadEpipolarConstantsInputs& in) {
    rg::BufferRef buffer = g.createBuffer("epipolar constants", {sizeof(EpipolarConstants)});
    auto pass = g.addPass("upload epipolar constants", rg::PassType::Transfer);
    buffer = pass.transferDst(buffer);
    pass.execute([values = in.values, buffer](rg::PassContext& ctx) {
        const EpipolarConstants& c = epipolarFrameOf(ctx.data(values)).constants;
        ctx.vk().CmdUpdateBuffer(ctx.cmd(), ctx.buffer(buffer), 0, sizeof c, &c);
    });
    return {buffer};
}

}  // namespace ls
