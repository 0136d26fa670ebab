#include "epipolar_nodes.h"
#include "refine_on_inscattering_frag.h"
#include "shared/pass_helpers.h"

namespace ls {

// One draw over the valid samples (stencil != 0); the shader keeps the fragments whose stencil
// must rise (see refine_on_inscattering.frag) and discards the rest.
RefinedSamples addRefineOnInscattering(rg::RenderGraph& g, const NodeInputs& in,
                                       rg::ImageRef interpolationSource, rg::ImageRef marched,
                                       rg::ImageRef epipolarStencil) {
    auto pass = g.addPass("refine on in-scattering differences", rg::PassType::Graphics);
    pass.uniformBuffer(in.constants);
    pass.sampled(marched);
    RefinedSamples out;
    out.interpolationSource = pass.storageReadWrite(interpolationSource);
    out.epipolarStencil = pass.stencilWrite(epipolarStencil, rg::LoadOp::Load);
    pass.execute([in, marched, sources = out.interpolationSource](rg::PassContext& ctx) {
        rg::GraphicsPipelineDesc desc =
            fullscreenPipeline(rg::spirv(ls_spirv::refine_on_inscattering_frag), ctx,
                               {uniformBinding(0), sampledBinding(1), storageBinding(2)});
        desc.stencilTest = true;  // every valid sample: 0 != stencil
        desc.stencil = {VK_STENCIL_OP_KEEP,
                        VK_STENCIL_OP_INCREMENT_AND_CLAMP,
                        VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_NOT_EQUAL,
                        0xff,
                        0xff,
                        0};
        const auto& p = in.shared->pipelines.graphics(
            pipelineKey("refine on in-scattering differences", ctx), desc);
        p.bind(ctx.cmd());
        vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 0);
        frameSet(ctx, in.constants)
            .sampled(1, ctx.view(marched), ctx.layout(marched), in.shared->samplers.nearest())
            .storage(2, ctx.view(sources))
            .push(ctx.device(), ctx.cmd(), p);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return out;
}

}  // namespace ls
