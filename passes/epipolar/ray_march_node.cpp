#include "epipolar_nodes.h"
#include "epipolar_shaders.h"
#include "ray_march_frag_variants.h"
#include "shared/pass_helpers.h"
#include "shared/shader_variant.h"

namespace ls {

// The plain build has no counter and no atomics; a point light's cube map comes without light
// color (refused with it).
rg::ShaderCode rayMarchShader(const ScatterSpec& spec, bool countSteps) {
    return pickShader(ls_spirv::ray_march_frag_variants,
                      {{"LS_NEEDS_TABLE", spec.light != LightKind::Directional},
                       {"LS_LIGHT_COLOR", spec.lightColor && !spec.cubeShadow},
                       {"LS_CUBE_SHADOW", spec.cubeShadow},
                       {"LS_TREES", spec.minMaxTrees},
                       {"LS_COUNT_STEPS", countSteps}});
}

EpipolarRayMarch addEpipolarRayMarch(rg::RenderGraph& g, const NodeInputs& in,
                                     const EpipolarSizes& s, const EpipolarRayMarchInputs& i) {
    const bool adds = i.accumulate.valid() && !i.overwrite;
    rg::ImageRef marched =
        i.accumulate.valid() ? i.accumulate
                             : g.createImage("in-scattering (ray-marched samples)",
                                             rg::ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT,
                                                                     s.samples, s.slices));
    const bool trees = i.trees.valid();
    auto pass =
        g.addPass(trees ? "ray march with min/max trees" : "ray march", rg::PassType::Graphics);
    const auto& sm = samplersOf(in.shared);
    rg::BindingTable table = frameTable(pass, in.constants);
    table.sampled(LS_BINDING_MARCH_COORDINATES, i.coordinates, sm.nearest())
        .sampled(LS_BINDING_MARCH_EPIPOLAR_Z, i.epipolarZ, sm.nearest())
        .sampled(LS_BINDING_MARCH_UV_FRAME, i.sliceUvFrame, sm.nearest())
        .sampledIfValid(LS_BINDING_MARCH_TREES, i.trees, sm.nearest());
    addMarchInputs(table, in);
    const rg::BufferRef counts =
        table.storageBufferReadWriteIfValid(LS_BINDING_MARCH_STEP_COUNTS, i.stepCounts);
    pass.stencilTest(i.epipolarStencil);
    pass.countSamples();  // the samples marched (FrameReport's PassTime::samples)
    marched =
        pass.colorAttachment(marched, i.accumulate.valid() ? rg::LoadOp::Load : rg::LoadOp::Clear);
    pass.execute([in, table, trees, adds, counts](rg::PassContext& ctx) {
        // A cube face out of view adds nothing (the first face's pass writes every sample's alpha).
        if (adds && !in.shared->inView()) return;
        ScatterSpec spec = in.shared->spec;
        spec.minMaxTrees = trees;
        auto desc = fullscreenPipeline(rayMarchShader(spec, counts.valid()), ctx, table.layout());
        desc.specialization = spec.constants();
        desc.stencilTest = true;
        desc.stencil = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_EQUAL, 0xff, 0, 2};
        if (adds) {
            desc.blend = rg::BlendMode::Additive;
            desc.colorWriteMask =
                VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT;
        }
        const auto& p = in.shared->pipelines.graphics(
            std::string(adds ? "ray march (adding a face)" : "ray march") +
                (counts.valid() ? ", counting" : ""),
            desc);
        p.bind(ctx.cmd());
        vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 2);
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return {marched, counts};
}

}  // namespace ls
