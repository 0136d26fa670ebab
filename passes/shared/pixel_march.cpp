#include "pixel_march.h"

#include "pass_helpers.h"
#include "pixel_march_directional_color_frag.h"
#include "pixel_march_directional_frag.h"
#include "pixel_march_table_color_frag.h"
#include "pixel_march_table_cube_frag.h"
#include "pixel_march_table_frag.h"

namespace ls {
namespace {

rg::ShaderCode pixelMarchShader(const ScatterSpec& spec) {
    const bool table = spec.light != LightKind::Directional;
    // A point light's cube map (light color is refused with it).
    if (spec.cubeShadow) return rg::spirv(ls_spirv::pixel_march_table_cube_frag);
    if (table) return spec.lightColor ? rg::spirv(ls_spirv::pixel_march_table_color_frag)
                                      : rg::spirv(ls_spirv::pixel_march_table_frag);
    return spec.lightColor ? rg::spirv(ls_spirv::pixel_march_directional_color_frag)
                           : rg::spirv(ls_spirv::pixel_march_directional_frag);
}

}  // namespace

void declarePixelMarch(rg::PassBuilder& pass, const NodeInputs& in) {
    pass.uniformBuffer(in.constants);
    pass.sampled(in.depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    declareMarchInputs(pass, in);
}

void drawPixelMarch(rg::PassContext& ctx, const NodeInputs& in,
                    const PixelMarchDraw& draw) {
    const ScatterSpec& spec = in.shared->spec;
    std::vector<rg::Binding> b{uniformBinding(0), sampledBinding(1)};
    appendMarchBindings(b, in);
    auto desc = fullscreenPipeline(pixelMarchShader(spec), ctx, b);
    desc.pushConstantBytes = 4;
    desc.specialization = spec.constants();
    if (draw.whereStencilIsOne) {
        desc.stencilTest = true;
        desc.stencil = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_EQUAL, 0xff, 0, 1};
    }
    const auto& p =
        in.shared->pipelines.graphics(pipelineKey(draw.pipeline, ctx, spec.key()), desc);
    p.bind(ctx.cmd());
    if (draw.whereStencilIsOne)
        vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
    auto set = frameSet(ctx, in.constants);
    set.sampled(1, ctx.view(in.depth, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.depth), in.shared->samplers.nearest());
    pushMarchInputs(set, ctx, in);
    set.push(ctx.device(), ctx.cmd(), p);
    p.push(ctx.cmd(), draw.maxSteps);
    vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
}

}  // namespace ls
