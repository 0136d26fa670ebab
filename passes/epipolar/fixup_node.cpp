#include "shared/pass_helpers.h"
#include "epipolar_nodes.h"

namespace ls {

// Pixels the unwarp could not interpolate (stencil 1) are ray-marched on their own, without trees.
rg::ImageRef addFixup(rg::RenderGraph& g, const NodeInputs& in, rg::ImageRef cameraZ,
                      rg::ImageRef cameraStencil, rg::ImageRef screenInscatter) {
    auto pass = g.addPass("fix-up ray march", rg::PassType::Graphics);
    pass.uniformBuffer(in.constants);
    pass.sampled(cameraZ);
    declareMarchInputs(pass, in);
    pass.stencilTest(cameraStencil);
    const rg::ImageRef out = pass.colorAttachment(screenInscatter, rg::LoadOp::Load);
    pass.execute([in, cameraZ](rg::PassContext& ctx) {
        const ScatterSpec& spec = in.shared->spec;
        std::vector<rg::Binding> b{uniformBinding(0), sampledBinding(1)};
        appendMarchBindings(b, in);
        auto desc = fullscreenPipeline(marchShader(MarchShader::BruteForce, spec), ctx, b);
        desc.pushConstantBytes = 4;
        desc.specialization = spec.constants();
        desc.stencilTest = true;
        desc.stencil = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_EQUAL, 0xff, 0, 1};
        const auto& p = in.shared->pipelines.graphics(pipelineKey("fix-up", ctx, spec.key()), desc);
        p.bind(ctx.cmd());
        vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
        auto set = frameSet(ctx, in.constants);
        set.sampled(1, ctx.view(cameraZ), ctx.layout(cameraZ), in.shared->samplers.nearest());
        pushMarchInputs(set, ctx, in);
        set.push(ctx.device(), ctx.cmd(), p);
        const uint32_t maxSteps = static_cast<uint32_t>(in.shared->constants.epipolar2.y);
        p.push(ctx.cmd(), maxSteps);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return out;
}

}  // namespace ls
