#include "pass_helpers.h"
#include "shared_nodes.h"
#include "unshadowed_directional_frag.h"
#include "unshadowed_table_frag.h"

namespace ls {
namespace {

rg::ShaderCode unshadowedShader(const ScatterSpec& spec) {
    return spec.light != LightKind::Directional ? rg::spirv(ls_spirv::unshadowed_table_frag)
                                                : rg::spirv(ls_spirv::unshadowed_directional_frag);
}

}  // namespace

rg::ImageRef addUnshadowed(rg::RenderGraph& graph, const NodeInputs& in) {
    rg::ImageRef lin = graph.createImage("in-scattering (screen)",
                                         rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    auto pass = graph.addPass("unshadowed in-scattering", rg::PassType::Graphics);
    pass.uniformBuffer(in.constants);
    pass.sampled(in.depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    declareMarchInputs(pass, in);  // the table; an unshadowed frame has nothing else
    lin = pass.colorAttachment(lin, rg::LoadOp::DontCare);
    pass.execute([in](rg::PassContext& ctx) {
        const ScatterSpec& spec = in.shared->spec;
        std::vector<rg::Binding> b{uniformBinding(0), sampledBinding(1)};
        appendMarchBindings(b, in);
        auto desc = fullscreenPipeline(unshadowedShader(spec), ctx, b);
        desc.specialization = spec.constants();
        const auto& p = in.shared->pipelines.graphics(
            pipelineKey("unshadowed in-scattering", ctx, spec.key()), desc);
        p.bind(ctx.cmd());
        auto set = frameSet(ctx, in.constants);
        set.sampled(1, ctx.view(in.depth, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.depth), in.shared->samplers.nearest());
        pushMarchInputs(set, ctx, in);
        set.push(ctx.device(), ctx.cmd(), p);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return lin;
}

}  // namespace ls
