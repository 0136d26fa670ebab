#include "common/pass_helpers.h"
#include "method_nodes.h"

namespace ls {

rg::ImageRef addUnshadowed(rg::RenderGraph& graph, const NodeInputs& in, rg::ImageRef cameraZ) {
    rg::ImageRef lin = graph.createImage("in-scattering (screen)",
                                         rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    auto pass = graph.addPass("unshadowed in-scattering", rg::PassType::Graphics);
    pass.uniformBuffer(in.constants);
    pass.sampled(cameraZ);
    if (in.table.valid()) pass.sampled(in.table);
    lin = pass.colorAttachment(lin, rg::LoadOp::DontCare);
    pass.execute([in, cameraZ](rg::PassContext& ctx) {
        const ScatterSpec& spec = in.shared->spec;
        std::vector<rg::Binding> b{uniformBinding(0), sampledBinding(1)};
        if (in.table.valid()) b.push_back(sampledBinding(7));
        auto desc = fullscreenPipeline(marchShader(MarchShader::Unshadowed, spec), ctx, b);
        desc.specialization = spec.constants();
        const auto& p = in.shared->pipelines.graphics(
            pipelineKey("unshadowed in-scattering", ctx, spec.key()), desc);
        p.bind(ctx.cmd());
        const auto& s = in.shared->samplers;
        auto set = frameSet(ctx, in.constants);
        set.sampled(1, ctx.view(cameraZ), ctx.layout(cameraZ), s.nearest());
        if (in.table.valid()) set.sampled(7, ctx.view(in.table), ctx.layout(in.table), s.nearest());
        set.push(ctx.device(), ctx.cmd(), p);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return lin;
}

}  // namespace ls
