#include "pixel_march.h"

#include "composite_target.h"
#include "pass_helpers.h"
#include "pixel_march_frag_variants.h"
#include "shader_variant.h"
#include "shared_shaders.h"

namespace ls {
namespace {

// pixel_march.frag's push block, plain and compositing (its fields written once, in
// pixel_march_push_fields.h).
#define LS_UINT uint32_t
struct PixelMarchPush {
#define LS_PIXEL_MARCH_COMPOSITES 0
#include "shaders/shared/pixel_march_push_fields.h"
#undef LS_PIXEL_MARCH_COMPOSITES
};
struct FixupPush {
#define LS_PIXEL_MARCH_COMPOSITES 1
#include "shaders/shared/pixel_march_push_fields.h"
#undef LS_PIXEL_MARCH_COMPOSITES
};
#undef LS_UINT

}  // namespace

// A point light's cube map comes without light color (refused with it). Without a shadow map the
// march is an unshadowed light's with a color (addUnshadowed), its only reason to march.
rg::ShaderCode pixelMarchShader(const ScatterSpec& spec, bool shadowMap) {
    return pickShader(ls_spirv::pixel_march_frag_variants,
                      {{"LS_NEEDS_TABLE", spec.light != LightType::Directional},
                       {"LS_LIGHT_COLOR", spec.lightColor && !spec.cubeShadow},
                       {"LS_CUBE_SHADOW", spec.cubeShadow},
                       {"LS_NO_SHADOW_MAP", !shadowMap},
                       {"LS_COMPOSITE", 0},
                       {"LS_COLOR_RGBA32F", 0},
                       {"LS_WITH_OUTPUT", 0},
                       {"LS_SPLIT", 0}});
}

rg::ShaderCode fixupShader(const ScatterSpec& spec, const CompositeVariant& target) {
    return pickCompositeShader(ls_spirv::pixel_march_frag_variants,
                               {{"LS_NEEDS_TABLE", spec.light != LightType::Directional},
                                {"LS_LIGHT_COLOR", spec.lightColor && !spec.cubeShadow},
                                {"LS_CUBE_SHADOW", spec.cubeShadow},
                                {"LS_NO_SHADOW_MAP", 0},
                                {"LS_COMPOSITE", 1}},
                               target);
}

rg::BindingTable declarePixelMarch(rg::PassBuilder& pass, const ChainContext& chain,
                                   const LightImages& light, VkPipelineStageFlags2 frameStages) {
    rg::BindingTable table = frameTable(pass, chain.constants, frameStages);
    table.sampled(LS_BINDING_DEPTH, chain.depth, samplersOf(chain.shared).nearest(),
                  VK_IMAGE_ASPECT_DEPTH_BIT);
    addMarchInputs(table, chain.shared, light);
    return table;
}

void drawPixelMarch(rg::PassContext& ctx, const Shared& shared, const ScatterSpec& lightSpec,
                    const rg::BindingTable& table, const PixelMarchDraw& draw) {
    // The variant follows from the light's images declared in the table, not from the spec's flag.
    ScatterSpec spec = lightSpec;
    spec.lightColor = table.has(LS_BINDING_LIGHT_COLOR);
    auto desc = fullscreenPipeline(draw.composite
                                       ? fixupShader(spec, compositeVariant(ctx, *draw.composite))
                                       : pixelMarchShader(spec, table.has(LS_BINDING_SHADOW_MAP)),
                                   ctx, table.layout());
    if (draw.vertex.words != nullptr) desc.vertex = draw.vertex;
    desc.pushConstantBytes = draw.composite ? sizeof(FixupPush) : sizeof(PixelMarchPush);
    desc.specialization = spec.constants();
    if (draw.whereStencilIsZero) {
        desc.stencilTest = true;
        desc.stencil = {VK_STENCIL_OP_KEEP,
                        VK_STENCIL_OP_KEEP,
                        VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_EQUAL,
                        0xff,
                        0,
                        0};
    }
    const auto& p = shared->pipelines.graphics(draw.pipeline, desc);
    p.bind(ctx.cmd());
    if (draw.whereStencilIsZero)
        ctx.vk().CmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 0);
    table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
    if (draw.composite) {
        p.push(ctx.cmd(), FixupPush{draw.maxSteps, draw.addOnly ? 1u : 0u});
    } else {
        p.push(ctx.cmd(), PixelMarchPush{draw.maxSteps});
    }
    ctx.vk().CmdDraw(ctx.cmd(), draw.vertices, 1, 0, 0);
}

}  // namespace ls
