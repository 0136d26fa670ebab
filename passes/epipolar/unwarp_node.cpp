#include "epipolar_nodes.h"
#include "epipolar_shaders.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/composite_target.h"
#include "shared/pass_helpers.h"
#include "shared/shader_variant.h"
#include "unwarp_frag_variants.h"
#include "window_wedge_vert.h"

namespace ls {
namespace {

// unwarp.frag's push block (its fields written once, in unwarp_push_fields.h).
struct UnwarpPush {
#define LS_INT int32_t
#include "shaders/epipolar/unwarp_push_fields.h"
#undef LS_INT
};

}  // namespace

rg::ShaderCode windowWedgeShader() {
    return rg::spirv(ls_spirv::window_wedge_vert);
}

rg::ShaderCode unwarpShader(bool table, const CompositeVariant& target, bool blend) {
    return pickCompositeShader(ls_spirv::unwarp_frag_variants,
                               {{"LS_NEEDS_TABLE", table}, {"LS_BLEND", blend}}, target);
}

// One draw: the bilateral unwarp composites every pixel it can serve into the engine's color; with
// fix-up on, each served pixel also writes 1 into a cleared stencil (the fragments it cannot serve
// are discarded), and the fix-up marches the zeros. Where the target blends
// (CompositeTarget::blend) the color is an attachment too; with neither the pass renders over the
// screen.
UnwarpOutputs addUnwarp(rg::RenderGraph& g, const UnwarpInputs& in, const UnwarpOptions& options) {
    const bool markForFixup = options.markForFixup;
    UnwarpOutputs out;
    auto pass = g.addPass("unwarp epipolar to screen", rg::PassType::Graphics);
    const auto& sm = samplersOf(in.chain.shared);
    const bool addOnly = in.target.addOnly;
    rg::BindingTable table =
        epipolarTable(pass, in.chain, in.epipolar, addOnly ? kVertexAndFragmentStages : 0);
    table.sampled(LS_BINDING_UNWARP_END_POINTS, in.sliceEndPoints, sm.nearest())
        .sampled(LS_BINDING_UNWARP_EPIPOLAR_Z, in.epipolarZ, sm.nearest())
        .sampled(LS_BINDING_UNWARP_INSCATTER, in.interpolated, sm.nearest())
        .sampled(LS_BINDING_UNWARP_DEPTH, in.chain.depth, sm.nearest(), VK_IMAGE_ASPECT_DEPTH_BIT)
        .sampledIfValid(LS_BINDING_POINT_TABLE, in.light.table, sm.nearest());
    bool blend = false;
    out.composited = addBlendedCompositeTarget(pass, table, in.target, blend);
    if (markForFixup) {
        const rg::ImageRef stencil =
            g.createImage("camera depth-stencil", rg::ImageDesc::screen(in.chain.depthStencil));
        out.cameraStencil = pass.stencilWrite(stencil, rg::LoadOp::Clear, 0);
    } else if (!blend) {
        pass.renderArea(in.chain.screen);
    }
    const CompositeOutputs written = out.composited;
    pass.execute([shared = in.chain.shared, spec = in.chain.spec, values = in.chain.values,
                  light = in.light, table, written, markForFixup, addOnly,
                  blend](rg::PassContext& ctx) {
        // A later light adds nothing outside its screen rectangle; the first applies the
        // extinction everywhere. (The fix-up keeps to the same rectangle.)
        if (addOnly && !scissorToLight(ctx, values)) return;
        auto desc = fullscreenPipeline(
            unwarpShader(light.table.valid(), compositeVariant(ctx, written), blend), ctx,
            table.layout());
        if (blend) desc.blend = rg::BlendMode::DualSourceMultiplyAdd;
        // A later light draws only its lines' wedge: outside it, it adds nothing.
        if (addOnly) desc.vertex = windowWedgeShader();
        desc.pushConstantBytes = 8;
        desc.specialization = spec.constants();
        if (markForFixup) {
            desc.stencilTest = true;
            desc.stencil = {VK_STENCIL_OP_KEEP,
                            VK_STENCIL_OP_REPLACE,
                            VK_STENCIL_OP_KEEP,
                            VK_COMPARE_OP_ALWAYS,
                            0xff,
                            0xff,
                            1};
        }
        const auto& p = shared->pipelines.graphics("unwarp", desc);
        p.bind(ctx.cmd());
        if (markForFixup)
            ctx.vk().CmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        p.push(ctx.cmd(), UnwarpPush{markForFixup ? 1 : 0, addOnly ? 1 : 0});
        ctx.vk().CmdDraw(ctx.cmd(), addOnly ? kWedgeVertices : 3, 1, 0, 0);
    });
    return out;
}

}  // namespace ls
