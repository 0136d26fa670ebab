#include "epipolar_nodes.h"
#include "epipolar_shaders.h"
#include "march_cover_vert.h"
#include "mark_ray_march_frag.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"

namespace ls {

rg::ShaderCode marchCoverShader() {
    return rg::spirv(ls_spirv::march_cover_vert);
}

// The march's stencil holds 0, kFirstMarch or kRefinementMarch per sample, in the march's order.
// The first marking clears it and writes kFirstMarch; the refinement's writes kRefinementMarch
// where bit 1 (kFirstMarch's) is clear, so that the second march takes only the samples added.
rg::ImageRef addMarkRayMarchSamples(rg::RenderGraph& g, const MarkRayMarchInputs& in,
                                    const EpipolarSizes& s) {
    const bool refinement = in.marchStencil.valid();
    // With the list, only the texels that can be marked are drawn (the refinement's marking, which
    // has no list, draws them all).
    const bool cover = s.marchList && !refinement;
    const VkPipelineStageFlags2 stages = cover ? kVertexAndFragmentStages : 0;
    auto pass = g.addPass("mark ray-marching samples", rg::PassType::Graphics);
    const auto& sm = samplersOf(in.chain.shared);
    rg::BindingTable table = epipolarTable(pass, in.chain, in.epipolar, stages);
    table.sampled(LS_BINDING_INTERPOLATION_SOURCE, in.interpolationSource, sm.nearest())
        .sampled(LS_BINDING_SOURCES_EPIPOLAR_Z, in.epipolarZ, sm.nearest())
        .storageBufferRead(LS_BINDING_MARCH_LIST, in.marchList, stages);
    const rg::ImageRef stencil =
        refinement
            ? in.marchStencil
            : g.createImage("epipolar depth-stencil",
                            rg::ImageDesc::absolute(in.chain.depthStencil, s.marchExtent().width,
                                                    s.marchExtent().height));
    const rg::ImageRef marked =
        pass.stencilWrite(stencil, refinement ? rg::LoadOp::Load : rg::LoadOp::Clear, 0);
    const uint32_t vertices = cover ? marchCoverVertices(s.marchPhases) : 3;
    pass.execute(
        [shared = in.chain.shared, table, refinement, cover, vertices](rg::PassContext& ctx) {
            rg::GraphicsPipelineDesc desc =
                fullscreenPipeline(rg::spirv(ls_spirv::mark_ray_march_frag), ctx, table.layout());
            if (cover) desc.vertex = marchCoverShader();
            desc.stencilTest = true;
            const uint32_t value = refinement ? kRefinementMarch : kFirstMarch;
            desc.stencil = {VK_STENCIL_OP_KEEP,
                            VK_STENCIL_OP_REPLACE,
                            VK_STENCIL_OP_KEEP,
                            refinement ? VK_COMPARE_OP_NOT_EQUAL : VK_COMPARE_OP_ALWAYS,
                            kFirstMarch,
                            0xff,
                            value};
            const auto& p = shared->pipelines.graphics(
                refinement ? "mark ray-marching samples (refinement)" : "mark ray-marching samples",
                desc);
            p.bind(ctx.cmd());
            ctx.vk().CmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, value);
            table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
            ctx.vk().CmdDraw(ctx.cmd(), vertices, 1, 0, 0);
        });
    return marked;
}

}  // namespace ls
