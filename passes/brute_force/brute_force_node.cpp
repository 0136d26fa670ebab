#include "brute_force_node.h"

#include "shared/pass_helpers.h"

namespace ls {

rg::ImageRef addBruteForce(rg::RenderGraph& graph, const NodeInputs& in, rg::ImageRef cameraZ) {
    rg::ImageRef lin = graph.createImage("in-scattering (screen)",
                                         rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    auto pass = graph.addPass("brute-force ray march", rg::PassType::Graphics);
    pass.uniformBuffer(in.constants);
    pass.sampled(cameraZ);
    declareMarchInputs(pass, in);
    lin = pass.colorAttachment(lin, rg::LoadOp::DontCare);
    pass.execute([in, cameraZ](rg::PassContext& ctx) {
        const ScatterSpec& spec = in.shared->spec;
        std::vector<rg::Binding> b{uniformBinding(0), sampledBinding(1)};
        appendMarchBindings(b, in);
        auto desc = fullscreenPipeline(marchShader(MarchShader::BruteForce, spec), ctx, b);
        desc.pushConstantBytes = 4;
        desc.specialization = spec.constants();
        const auto& p = in.shared->pipelines.graphics(
            pipelineKey("brute-force ray march", ctx, spec.key()), desc);
        p.bind(ctx.cmd());
        auto set = frameSet(ctx, in.constants);
        set.sampled(1, ctx.view(cameraZ), ctx.layout(cameraZ), in.shared->samplers.nearest());
        pushMarchInputs(set, ctx, in);
        set.push(ctx.device(), ctx.cmd(), p);
        const uint32_t everyTexel = 0;
        p.push(ctx.cmd(), everyTexel);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return lin;
}

}  // namespace ls
