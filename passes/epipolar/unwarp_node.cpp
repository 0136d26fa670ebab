#include "epipolar_nodes.h"
#include "shared/composite_target.h"
#include "shared/pass_helpers.h"
#include "unwarp_directional_rgba16f_frag.h"
#include "unwarp_directional_rgba16f_out_frag.h"
#include "unwarp_directional_rgba32f_frag.h"
#include "unwarp_directional_rgba32f_out_frag.h"
#include "unwarp_table_rgba16f_frag.h"
#include "unwarp_table_rgba16f_out_frag.h"
#include "unwarp_table_rgba32f_frag.h"
#include "unwarp_table_rgba32f_out_frag.h"

namespace ls {
namespace {

const CompositeVariants kDirectional{
    rg::spirv(ls_spirv::unwarp_directional_rgba16f_frag),
    rg::spirv(ls_spirv::unwarp_directional_rgba16f_out_frag),
    rg::spirv(ls_spirv::unwarp_directional_rgba32f_frag),
    rg::spirv(ls_spirv::unwarp_directional_rgba32f_out_frag)};
const CompositeVariants kTable{
    rg::spirv(ls_spirv::unwarp_table_rgba16f_frag),
    rg::spirv(ls_spirv::unwarp_table_rgba16f_out_frag),
    rg::spirv(ls_spirv::unwarp_table_rgba32f_frag),
    rg::spirv(ls_spirv::unwarp_table_rgba32f_out_frag)};

}  // namespace

// One draw: the bilateral unwarp composites every pixel it can serve into the engine's color; with
// fix-up on, each served pixel also writes 1 into a cleared stencil (the fragments it cannot serve
// are discarded), and the fix-up marches the zeros. Without fix-up there is no attachment: the pass
// renders over the screen.
UnwarpOutputs addUnwarp(rg::RenderGraph& g, const NodeInputs& in, const UnwarpInputs& i,
                        const CompositeTarget& target, bool markForFixup) {
    UnwarpOutputs out;
    auto pass = g.addPass("unwarp epipolar to screen", rg::PassType::Graphics);
    pass.uniformBuffer(in.constants);
    pass.sampled(i.sliceEndPoints);
    pass.sampled(i.epipolarZ);
    pass.sampled(i.interpolated);
    pass.sampled(in.depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    if (in.table.valid()) pass.sampled(in.table);
    out.composited = declareCompositeTarget(pass, target);
    if (markForFixup) {
        const rg::ImageRef stencil =
            g.createImage("camera depth-stencil", rg::ImageDesc::screen(in.depthStencil));
        out.cameraStencil = pass.stencilWrite(stencil, rg::LoadOp::Clear, 0);
    } else {
        pass.renderArea(in.screen);
    }
    const CompositeOutputs written = out.composited;
    const bool addOnly = target.addOnly;
    pass.execute([in, i, written, markForFixup, addOnly](rg::PassContext& ctx) {
        const ScatterSpec& spec = in.shared->spec;
        std::vector<rg::Binding> b{uniformBinding(0), sampledBinding(1), sampledBinding(2),
                                   sampledBinding(3), sampledBinding(4)};
        if (in.table.valid()) b.push_back(sampledBinding(7));
        appendCompositeBindings(b, written);
        auto desc = fullscreenPipeline((in.table.valid() ? kTable : kDirectional).pick(ctx, written), ctx, b);
        desc.pushConstantBytes = 8;
        desc.specialization = spec.constants();
        if (markForFixup) {
            desc.stencilTest = true;
            desc.stencil = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_REPLACE, VK_STENCIL_OP_KEEP,
                            VK_COMPARE_OP_ALWAYS, 0xff, 0xff, 1};
        }
        const std::string variant = spec.key() + "/" + compositeKey(ctx, written) +
                                    (markForFixup ? "/marks" : "");
        const auto& p = in.shared->pipelines.graphics(pipelineKey("unwarp", ctx, variant), desc);
        const auto& sm = in.shared->samplers;
        p.bind(ctx.cmd());
        if (markForFixup) vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
        auto set = frameSet(ctx, in.constants);
        set.sampled(1, ctx.view(i.sliceEndPoints), ctx.layout(i.sliceEndPoints), sm.nearest())
            .sampled(2, ctx.view(i.epipolarZ), ctx.layout(i.epipolarZ), sm.nearest())
            .sampled(3, ctx.view(i.interpolated), ctx.layout(i.interpolated), sm.nearest())
            .sampled(4, ctx.view(in.depth, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.depth), sm.nearest());
        if (in.table.valid()) set.sampled(7, ctx.view(in.table), ctx.layout(in.table), sm.nearest());
        pushCompositeTarget(set, ctx, written);
        set.push(ctx.device(), ctx.cmd(), p);
        const int32_t push[2] = {markForFixup ? 1 : 0, addOnly ? 1 : 0};
        p.push(ctx.cmd(), push);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return out;
}

}  // namespace ls
