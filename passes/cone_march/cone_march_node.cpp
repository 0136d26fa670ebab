#include "cone_march_node.h"

#include "shared/pass_helpers.h"
#include "cone_march_color_frag.h"
#include "cone_march_plain_frag.h"
#include "cone_march_shadowed_color_frag.h"
#include "cone_march_shadowed_frag.h"

namespace ls {
namespace {

// Bindings that only some frames have are build-time variants, so a pipeline never declares a
// descriptor it is not given.
rg::ShaderCode coneMarchShader(bool shadowMap, bool lightColor) {
    if (shadowMap)
        return lightColor ? rg::spirv(ls_spirv::cone_march_shadowed_color_frag)
                          : rg::spirv(ls_spirv::cone_march_shadowed_frag);
    return lightColor ? rg::spirv(ls_spirv::cone_march_color_frag) : rg::spirv(ls_spirv::cone_march_plain_frag);
}

}  // namespace

rg::ImageRef addConeMarch(rg::RenderGraph& graph, const Shared& shared, const ConeMarchInputs& in,
                          const ConeMarchOptions& options) {
    rg::ImageRef lin = graph.createImage("in-scattering (screen)",
                                         rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    const std::string name = options.coneLimited ? "cone-limited ray march (seed 003)"
                                                 : "naive ray march (seed 003's baseline)";
    auto pass = graph.addPass(name, rg::PassType::Graphics);
    pass.uniformBuffer(in.constants);
    pass.sampled(in.depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    if (in.shadowMap.valid()) pass.sampled(in.shadowMap, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    if (in.lightColor.valid()) pass.sampled(in.lightColor);
    lin = pass.colorAttachment(lin, rg::LoadOp::DontCare);
    pass.execute([shared, in, options](rg::PassContext& ctx) {
        const ScatterSpec& spec = shared->spec;
        const bool shadow = in.shadowMap.valid(), color = in.lightColor.valid();
        std::vector<rg::Binding> bindings{uniformBinding(0), sampledBinding(1)};
        if (shadow) bindings.push_back(sampledBinding(6));
        if (color) bindings.push_back(sampledBinding(8));
        auto desc = fullscreenPipeline(coneMarchShader(shadow, color), ctx, std::move(bindings));
        desc.specialization = spec.constants();
        desc.specialization.set(10, options.samples).set(11, options.coneLimited).set(12, options.jitter);
        const std::string variant = spec.key() + "/n" + std::to_string(options.samples) +
                                    (options.coneLimited ? "c" : "f") + (options.jitter ? "j" : "m") +
                                    (shadow ? "S" : "s") + (color ? "C" : "c");
        const auto& p = shared->pipelines.graphics(pipelineKey("cone march", ctx, variant), desc);
        p.bind(ctx.cmd());
        auto set = frameSet(ctx, in.constants);
        set.sampled(1, ctx.view(in.depth, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.depth), shared->samplers.nearest());
        if (shadow)
            set.sampled(6, ctx.view(in.shadowMap, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.shadowMap),
                        shared->samplers.nearest());
        if (color) set.sampled(8, ctx.view(in.lightColor), ctx.layout(in.lightColor), shared->samplers.linear());
        set.push(ctx.device(), ctx.cmd(), p);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return lin;
}

}  // namespace ls
