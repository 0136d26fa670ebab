#include "shared/pass_helpers.h"
#include "epipolar_nodes.h"
#include "slice_uv_frame_comp.h"

namespace ls {

void addSliceUvFrame(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                     EpipolarTextures& t) {
    t.sliceUvFrame = g.createImage("slice uv origin and direction",
                                   rg::ImageDesc::absolute(VK_FORMAT_R32G32B32A32_SFLOAT, s.slices, 1));
    auto pass = g.addPass("slice uv origin and direction", rg::PassType::Compute);
    pass.uniformBuffer(in.constants);
    pass.sampled(t.sliceEndPoints);
    t.sliceUvFrame = pass.storageWrite(t.sliceUvFrame);
    const EpipolarTextures tex = t;
    pass.execute([in, tex, s](rg::PassContext& ctx) {
        const auto& p = in.shared->pipelines.compute(
            "slice uv origin and direction", rg::spirv(ls_spirv::slice_uv_frame_comp),
            {uniformBinding(0), sampledBinding(1), storageBinding(2)}, 0, {});
        p.bind(ctx.cmd());
        frameSet(ctx, in.constants)
            .sampled(1, ctx.view(tex.sliceEndPoints), ctx.layout(tex.sliceEndPoints),
                     in.shared->samplers.nearest())
            .storage(2, ctx.view(tex.sliceUvFrame))
            .push(ctx.device(), ctx.cmd(), p);
        vkCmdDispatch(ctx.cmd(), groupCount(s.slices, 64), 1, 1);
    });
}

}  // namespace ls
