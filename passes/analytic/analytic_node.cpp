#include "analytic_node.h"

#include "analytic_frag.h"
#include "shared/pass_helpers.h"

namespace ls {

rg::ImageRef addAnalytic(rg::RenderGraph& graph, const Shared& shared, const AnalyticInputs& in) {
    rg::ImageRef lin = graph.createImage("in-scattering (screen)",
                                         rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    auto pass = graph.addPass("analytic in-scattering (seed 001)", rg::PassType::Graphics);
    pass.uniformBuffer(in.constants);
    pass.sampled(in.depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    lin = pass.colorAttachment(lin, rg::LoadOp::DontCare);
    pass.execute([shared, in](rg::PassContext& ctx) {
        const ScatterSpec& spec = shared->spec;
        auto desc = fullscreenPipeline(rg::spirv(ls_spirv::analytic_frag), ctx,
                                       {uniformBinding(0), sampledBinding(1)});
        desc.specialization = spec.constants();
        const auto& p = shared->pipelines.graphics(pipelineKey("analytic in-scattering", ctx, spec.key()), desc);
        p.bind(ctx.cmd());
        frameSet(ctx, in.constants)
            .sampled(1, ctx.view(in.depth, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.depth), shared->samplers.nearest())
            .push(ctx.device(), ctx.cmd(), p);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return lin;
}

}  // namespace ls
