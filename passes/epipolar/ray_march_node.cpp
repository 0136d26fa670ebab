#include "epipolar_nodes.h"
#include "ray_march_directional_color_count_frag.h"
#include "ray_march_directional_color_frag.h"
#include "ray_march_directional_color_trees_count_frag.h"
#include "ray_march_directional_color_trees_frag.h"
#include "ray_march_directional_count_frag.h"
#include "ray_march_directional_frag.h"
#include "ray_march_directional_trees_count_frag.h"
#include "ray_march_directional_trees_frag.h"
#include "ray_march_table_color_count_frag.h"
#include "ray_march_table_color_frag.h"
#include "ray_march_table_color_trees_count_frag.h"
#include "ray_march_table_color_trees_frag.h"
#include "ray_march_table_count_frag.h"
#include "ray_march_table_cube_count_frag.h"
#include "ray_march_table_cube_frag.h"
#include "ray_march_table_cube_trees_count_frag.h"
#include "ray_march_table_cube_trees_frag.h"
#include "ray_march_table_frag.h"
#include "ray_march_table_trees_count_frag.h"
#include "ray_march_table_trees_frag.h"
#include "shared/pass_helpers.h"

namespace ls {
namespace {

// A variant and its counting twin (LS_COUNT_STEPS): the plain one has no counter and no atomics.
struct RayMarchVariant {
    rg::ShaderCode plain, counting;
};
#define LS_RAY_MARCH_VARIANT(name)                             \
    RayMarchVariant {                                          \
        rg::spirv(ls_spirv::ray_march_##name##_frag),          \
            rg::spirv(ls_spirv::ray_march_##name##_count_frag) \
    }

RayMarchVariant rayMarchVariant(const ScatterSpec& spec) {
    const bool table = spec.light != LightKind::Directional;
    const bool color = spec.lightColor;
    // A point light's cube map (light color is refused with it).
    if (spec.cubeShadow)
        return spec.minMaxTrees ? LS_RAY_MARCH_VARIANT(table_cube_trees)
                                : LS_RAY_MARCH_VARIANT(table_cube);
    if (spec.minMaxTrees) {
        if (table)
            return color ? LS_RAY_MARCH_VARIANT(table_color_trees)
                         : LS_RAY_MARCH_VARIANT(table_trees);
        return color ? LS_RAY_MARCH_VARIANT(directional_color_trees)
                     : LS_RAY_MARCH_VARIANT(directional_trees);
    }
    if (table) return color ? LS_RAY_MARCH_VARIANT(table_color) : LS_RAY_MARCH_VARIANT(table);
    return color ? LS_RAY_MARCH_VARIANT(directional_color) : LS_RAY_MARCH_VARIANT(directional);
}
#undef LS_RAY_MARCH_VARIANT

}  // namespace

EpipolarRayMarch addEpipolarRayMarch(rg::RenderGraph& g, const EpipolarRayMarchInputs& in,
                                     const EpipolarRayMarchOptions& options) {
    const EpipolarSizes& s = options.sizes;
    const bool adds = in.accumulate.valid() && !options.overwrite;
    rg::ImageRef marched =
        in.accumulate.valid() ? in.accumulate
                              : g.createImage("in-scattering (ray-marched samples)",
                                              rg::ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT,
                                                                      s.samples, s.slices));
    // The variant follows from the handles given: trees or none, a light color or none.
    const bool trees = in.trees.valid(), color = in.light.lightColor.valid();
    auto pass =
        g.addPass(trees ? "ray march with min/max trees" : "ray march", rg::PassType::Graphics);
    const auto& sm = samplersOf(in.frame.shared);
    rg::BindingTable table = frameTable(pass, in.frame.constants);
    table.sampled(LS_BINDING_MARCH_COORDINATES, in.coordinates, sm.nearest())
        .sampled(LS_BINDING_MARCH_EPIPOLAR_Z, in.epipolarZ, sm.nearest())
        .sampled(LS_BINDING_MARCH_UV_FRAME, in.sliceUvFrame, sm.nearest())
        .sampledIfValid(LS_BINDING_MARCH_TREES, in.trees, sm.nearest());
    addMarchInputs(table, in.frame.shared, in.light);
    const rg::BufferRef counts =
        table.storageBufferReadWriteIfValid(LS_BINDING_MARCH_STEP_COUNTS, in.stepCounts);
    pass.stencilTest(in.epipolarStencil);
    pass.countSamples();  // the samples marched (FrameReport's PassTime::samples)
    marched =
        pass.colorAttachment(marched, in.accumulate.valid() ? rg::LoadOp::Load : rg::LoadOp::Clear);
    pass.execute([shared = in.frame.shared, table, trees, color, adds,
                  counts](rg::PassContext& ctx) {
        // A cube face out of view adds nothing (the first face's pass writes every sample's alpha).
        if (adds && !shared->inView()) return;
        ScatterSpec spec = shared->spec;
        spec.minMaxTrees = trees;
        spec.lightColor = color;
        const RayMarchVariant variant = rayMarchVariant(spec);
        auto desc = fullscreenPipeline(counts.valid() ? variant.counting : variant.plain, ctx,
                                       table.layout());
        desc.specialization = spec.constants();
        desc.stencilTest = true;
        desc.stencil = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_EQUAL, 0xff, 0, 2};
        if (adds) {
            desc.blend = rg::BlendMode::Additive;
            desc.colorWriteMask =
                VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT;
        }
        const auto& p = shared->pipelines.graphics(
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
