#include "shared/pass_helpers.h"
#include "epipolar_nodes.h"
#include "unwarp_directional_frag.h"
#include "unwarp_table_frag.h"

namespace ls {

// Two draws in one pass: the bilateral unwarp writes every pixel; then, with fix-up on, a
// stencil-only draw marks the pixels that no epipolar sample could serve.
UnwarpOutputs addUnwarp(rg::RenderGraph& g, const NodeInputs& in, const UnwarpInputs& i,
                        bool markForFixup) {
    UnwarpOutputs out;
    out.screenInscatter = g.createImage("in-scattering (screen)",
                                        rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    auto pass = g.addPass("unwarp epipolar to screen", rg::PassType::Graphics);
    pass.uniformBuffer(in.constants);
    pass.sampled(i.sliceEndPoints);
    pass.sampled(i.epipolarZ);
    pass.sampled(i.interpolated);
    pass.sampled(in.depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    if (in.table.valid()) pass.sampled(in.table);
    out.screenInscatter = pass.colorAttachment(out.screenInscatter, rg::LoadOp::DontCare);
    if (markForFixup) {
        const rg::ImageRef stencil =
            g.createImage("camera depth-stencil", rg::ImageDesc::screen(in.depthStencil));
        out.cameraStencil = pass.stencilWrite(stencil, rg::LoadOp::Clear, 0);
    }
    pass.execute([in, i, markForFixup](rg::PassContext& ctx) {
        const ScatterSpec& spec = in.shared->spec;
        std::vector<rg::Binding> b{uniformBinding(0), sampledBinding(1), sampledBinding(2),
                                   sampledBinding(3), sampledBinding(4)};
        if (in.table.valid()) b.push_back(sampledBinding(7));
        auto desc = fullscreenPipeline(in.table.valid() ? rg::spirv(ls_spirv::unwarp_table_frag)
                                                        : rg::spirv(ls_spirv::unwarp_directional_frag),
                                       ctx, b);
        desc.pushConstantBytes = 4;
        desc.specialization = spec.constants();
        const auto& write = in.shared->pipelines.graphics(pipelineKey("unwarp", ctx, spec.key()), desc);
        const auto& sm = in.shared->samplers;
        write.bind(ctx.cmd());
        auto set = frameSet(ctx, in.constants);
        set.sampled(1, ctx.view(i.sliceEndPoints), ctx.layout(i.sliceEndPoints), sm.nearest())
            .sampled(2, ctx.view(i.epipolarZ), ctx.layout(i.epipolarZ), sm.nearest())
            .sampled(3, ctx.view(i.interpolated), ctx.layout(i.interpolated), sm.nearest())
            .sampled(4, ctx.view(in.depth, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.depth), sm.nearest());
        if (in.table.valid()) set.sampled(7, ctx.view(in.table), ctx.layout(in.table), sm.nearest());
        set.push(ctx.device(), ctx.cmd(), write);
        int32_t mode = 0;
        write.push(ctx.cmd(), mode);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
        if (!markForFixup) return;
        desc.colorWriteMask = 0;
        desc.stencilTest = true;
        desc.stencil = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_REPLACE, VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_ALWAYS, 0xff, 0xff, 1};
        const auto& mark = in.shared->pipelines.graphics(pipelineKey("unwarp mark", ctx, spec.key()), desc);
        mark.bind(ctx.cmd());
        vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
        mode = 1;
        mark.push(ctx.cmd(), mode);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return out;
}

}  // namespace ls
