#include "common/pass_helpers.h"
#include "method_nodes.h"

namespace ls {

rg::ImageRef addBruteForce(rg::RenderGraph& graph, const NodeInputs& in, rg::ImageRef cameraZ) {
    rg::ImageRef lin = graph.createImage("in-scattering (screen)",
                                         rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    auto pass = graph.addPass("brute-force ray march", rg::PassType::Graphics);
    pass.uniformBuffer(in.constants);
    pass.sampled(cameraZ);
    pass.sampled(in.shadowMap, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    if (in.table.valid()) pass.sampled(in.table);
    if (in.lightColor.valid()) pass.sampled(in.lightColor);
    lin = pass.colorAttachment(lin, rg::LoadOp::DontCare);
    pass.execute([in, cameraZ](rg::PassContext& ctx) {
        const ScatterSpec& spec = in.shared->spec;
        std::vector<rg::Binding> b{uniformBinding(0), sampledBinding(1), sampledBinding(6)};
        if (in.table.valid()) b.push_back(sampledBinding(7));
        if (in.lightColor.valid()) b.push_back(sampledBinding(8));
        auto desc = fullscreenPipeline(marchShader(MarchShader::BruteForce, spec), ctx, b);
        desc.pushConstantBytes = 4;
        desc.specialization = spec.constants();
        const auto& p = in.shared->pipelines.graphics(
            pipelineKey("brute-force ray march", ctx, spec.key()), desc);
        p.bind(ctx.cmd());
        const auto& s = in.shared->samplers;
        auto set = frameSet(ctx, in.constants);
        set.sampled(1, ctx.view(cameraZ), ctx.layout(cameraZ), s.nearest())
            .sampled(6, ctx.view(in.shadowMap, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.shadowMap),
                     s.nearest());
        if (in.table.valid()) set.sampled(7, ctx.view(in.table), ctx.layout(in.table), s.nearest());
        if (in.lightColor.valid())
            set.sampled(8, ctx.view(in.lightColor), ctx.layout(in.lightColor), s.linear());
        set.push(ctx.device(), ctx.cmd(), p);
        const uint32_t everyTexel = 0;
        p.push(ctx.cmd(), everyTexel);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return lin;
}

}  // namespace ls
