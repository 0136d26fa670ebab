#include "pixel_march.h"

#include "composite_target.h"
#include "pass_helpers.h"
#include "pixel_march_frag_variants.h"
#include "shader_variant.h"
#include "shared_shaders.h"

namespace ls {

// A point light's cube map comes without light color (refused with it).
rg::ShaderCode pixelMarchShader(const ScatterSpec& spec) {
    return pickShader(ls_spirv::pixel_march_frag_variants,
                      {{"LS_NEEDS_TABLE", spec.light != LightKind::Directional},
                       {"LS_LIGHT_COLOR", spec.lightColor && !spec.cubeShadow},
                       {"LS_CUBE_SHADOW", spec.cubeShadow},
                       {"LS_COMPOSITE", 0},
                       {"LS_COLOR_RGBA32F", 0},
                       {"LS_WITH_OUTPUT", 0}});
}

rg::ShaderCode fixupShader(const ScatterSpec& spec, VkFormat color, bool withOutput) {
    return pickCompositeShader(ls_spirv::pixel_march_frag_variants,
                               {{"LS_NEEDS_TABLE", spec.light != LightKind::Directional},
                                {"LS_LIGHT_COLOR", spec.lightColor && !spec.cubeShadow},
                                {"LS_CUBE_SHADOW", spec.cubeShadow},
                                {"LS_COMPOSITE", 1}},
                               color, withOutput);
}

rg::BindingTable declarePixelMarch(rg::PassBuilder& pass, const NodeInputs& in) {
    rg::BindingTable table = frameTable(pass, in.constants);
    table.sampled(LS_BINDING_DEPTH, in.depth, samplersOf(in.shared).nearest(),
                  VK_IMAGE_ASPECT_DEPTH_BIT);
    addMarchInputs(table, in);
    return table;
}

void drawPixelMarch(rg::PassContext& ctx, const NodeInputs& in, const rg::BindingTable& table,
                    const PixelMarchDraw& draw) {
    const ScatterSpec& spec = in.shared->spec;
    auto desc =
        fullscreenPipeline(draw.composite ? fixupShader(spec, ctx.format(draw.composite->color),
                                                        draw.composite->inscatterOut.valid())
                                          : pixelMarchShader(spec),
                           ctx, table.layout());
    desc.pushConstantBytes = draw.composite ? 8 : 4;
    desc.specialization = spec.constants();
    if (draw.whereStencilIsZero) {
        desc.stencilTest = true;
        desc.stencil = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_EQUAL, 0xff, 0, 0};
    }
    const auto& p = in.shared->pipelines.graphics(draw.pipeline, desc);
    p.bind(ctx.cmd());
    if (draw.whereStencilIsZero)
        vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 0);
    table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
    if (draw.composite) {
        const uint32_t push[2] = {draw.maxSteps, draw.addOnly ? 1u : 0u};
        p.push(ctx.cmd(), push);
    } else {
        p.push(ctx.cmd(), draw.maxSteps);
    }
    vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
}

}  // namespace ls
