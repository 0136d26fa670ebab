#include "camera_z_comp.h"
#include "pass_helpers.h"
#include "shared_nodes.h"

namespace ls {

rg::ImageRef addCameraZ(rg::RenderGraph& graph, const NodeInputs& in) {
    rg::ImageRef z = graph.createImage("camera-space z", rg::ImageDesc::screen(VK_FORMAT_R32_SFLOAT));
    auto pass = graph.addPass("reconstruct camera-space z", rg::PassType::Compute);
    pass.uniformBuffer(in.constants);
    pass.sampled(in.depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    z = pass.storageWrite(z);
    pass.execute([in, z](rg::PassContext& ctx) {
        const auto& p = in.shared->pipelines.compute(
            "reconstruct camera-space z", rg::spirv(ls_spirv::camera_z_comp),
            {uniformBinding(0), sampledBinding(1), storageBinding(2)}, 0, {});
        p.bind(ctx.cmd());
        frameSet(ctx, in.constants)
            .sampled(1, ctx.view(in.depth, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.depth),
                     in.shared->samplers.nearest())
            .storage(2, ctx.view(z))
            .push(ctx.device(), ctx.cmd(), p);
        const VkExtent2D e = ctx.extent(z);
        vkCmdDispatch(ctx.cmd(), groupCount(e.width, 8), groupCount(e.height, 8), 1);
    });
    return z;
}

}  // namespace ls
