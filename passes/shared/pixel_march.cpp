#include "pixel_march.h"

#include "composite_target.h"
#include "pass_helpers.h"
#include "pixel_march_directional_color_frag.h"
#include "pixel_march_directional_frag.h"
#include "pixel_march_table_color_frag.h"
#include "pixel_march_table_cube_frag.h"
#include "pixel_march_table_frag.h"
#include "pixel_march_fixup_directional_rgba16f_frag.h"
#include "pixel_march_fixup_directional_rgba16f_out_frag.h"
#include "pixel_march_fixup_directional_rgba32f_frag.h"
#include "pixel_march_fixup_directional_rgba32f_out_frag.h"
#include "pixel_march_fixup_table_rgba16f_frag.h"
#include "pixel_march_fixup_table_rgba16f_out_frag.h"
#include "pixel_march_fixup_table_rgba32f_frag.h"
#include "pixel_march_fixup_table_rgba32f_out_frag.h"
#include "pixel_march_fixup_directional_color_rgba16f_frag.h"
#include "pixel_march_fixup_directional_color_rgba16f_out_frag.h"
#include "pixel_march_fixup_directional_color_rgba32f_frag.h"
#include "pixel_march_fixup_directional_color_rgba32f_out_frag.h"
#include "pixel_march_fixup_table_color_rgba16f_frag.h"
#include "pixel_march_fixup_table_color_rgba16f_out_frag.h"
#include "pixel_march_fixup_table_color_rgba32f_frag.h"
#include "pixel_march_fixup_table_color_rgba32f_out_frag.h"
#include "pixel_march_fixup_table_cube_rgba16f_frag.h"
#include "pixel_march_fixup_table_cube_rgba16f_out_frag.h"
#include "pixel_march_fixup_table_cube_rgba32f_frag.h"
#include "pixel_march_fixup_table_cube_rgba32f_out_frag.h"

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

// The fix-up's variants, compositing into the engine's color.
const CompositeVariants& fixupShaders(const ScatterSpec& spec) {
    static const CompositeVariants directional{
        rg::spirv(ls_spirv::pixel_march_fixup_directional_rgba16f_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_directional_rgba16f_out_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_directional_rgba32f_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_directional_rgba32f_out_frag)};
    static const CompositeVariants table{
        rg::spirv(ls_spirv::pixel_march_fixup_table_rgba16f_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_table_rgba16f_out_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_table_rgba32f_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_table_rgba32f_out_frag)};
    static const CompositeVariants directionalColor{
        rg::spirv(ls_spirv::pixel_march_fixup_directional_color_rgba16f_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_directional_color_rgba16f_out_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_directional_color_rgba32f_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_directional_color_rgba32f_out_frag)};
    static const CompositeVariants tableColor{
        rg::spirv(ls_spirv::pixel_march_fixup_table_color_rgba16f_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_table_color_rgba16f_out_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_table_color_rgba32f_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_table_color_rgba32f_out_frag)};
    static const CompositeVariants tableCube{
        rg::spirv(ls_spirv::pixel_march_fixup_table_cube_rgba16f_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_table_cube_rgba16f_out_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_table_cube_rgba32f_frag),
        rg::spirv(ls_spirv::pixel_march_fixup_table_cube_rgba32f_out_frag)};
    if (spec.cubeShadow) return tableCube;
    if (spec.light != LightKind::Directional) return spec.lightColor ? tableColor : table;
    return spec.lightColor ? directionalColor : directional;
}

}  // namespace

rg::BindingTable declarePixelMarch(rg::PassBuilder& pass, const FrameContext& frame,
                                   const LightImages& light) {
    rg::BindingTable table = frameTable(pass, frame.constants);
    table.sampled(LS_BINDING_DEPTH, frame.depth, samplersOf(frame.shared).nearest(),
                  VK_IMAGE_ASPECT_DEPTH_BIT);
    addMarchInputs(table, frame.shared, light);
    return table;
}

void drawPixelMarch(rg::PassContext& ctx, const Shared& shared, const rg::BindingTable& table,
                    const PixelMarchDraw& draw) {
    // The variant follows from the light's images declared in the table, not from the spec's flag.
    ScatterSpec spec = shared->spec;
    spec.lightColor = table.has(LS_BINDING_LIGHT_COLOR);
    auto desc = fullscreenPipeline(
        draw.composite ? fixupShaders(spec).pick(ctx, *draw.composite) : pixelMarchShader(spec),
        ctx, table.layout());
    desc.pushConstantBytes = draw.composite ? 8 : 4;
    desc.specialization = spec.constants();
    if (draw.whereStencilIsZero) {
        desc.stencilTest = true;
        desc.stencil = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_EQUAL, 0xff, 0, 0};
    }
    const auto& p = shared->pipelines.graphics(draw.pipeline, desc);
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
