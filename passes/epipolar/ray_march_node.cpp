#include "epipolar_nodes.h"
#include "epipolar_shaders.h"
#include "ray_march_frag_variants.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"
#include "shared/shader_variant.h"

namespace ls {

// The plain build has no counter and no atomics; a point light's cube map comes without light
// color (refused with it).
rg::ShaderCode rayMarchShader(const ScatterSpec& spec, bool trees, bool countSteps) {
    return pickShader(ls_spirv::ray_march_frag_variants,
                      {{"LS_NEEDS_TABLE", spec.light != LightType::Directional},
                       {"LS_LIGHT_COLOR", spec.lightColor && !spec.cubeShadow},
                       {"LS_CUBE_SHADOW", spec.cubeShadow},
                       {"LS_TREES", trees},
                       {"LS_COUNT_STEPS", countSteps}});
}

EpipolarRayMarch addEpipolarRayMarch(rg::RenderGraph& g, const EpipolarRayMarchInputs& in,
                                     const EpipolarRayMarchOptions& options) {
    const EpipolarSizes& s = options.sizes;
    rg::ImageRef marched =
        in.accumulate.valid()
            ? in.accumulate
            : g.createImage("in-scattering (ray-marched samples)",
                            rg::ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT,
                                                    s.marchExtent().width, s.marchExtent().height));
    // The variant follows from the handles given: trees or none, a light color or none.
    const bool trees = in.trees.valid(), color = in.light.lightColor.valid();
    auto pass =
        g.addPass(trees ? "ray march with min/max trees" : "ray march", rg::PassType::Graphics);
    const auto& sm = samplersOf(in.chain.shared);
    // The first march with the list draws what its marking could mark (march_cover.vert).
    const bool cover = s.marchList && options.marks == kFirstMarch;
    const VkPipelineStageFlags2 stages = cover ? kVertexAndFragmentStages : 0;
    rg::BindingTable table = epipolarTable(pass, in.chain, in.epipolar, stages);
    table.storageBufferRead(LS_BINDING_MARCH_LIST, in.marchList, stages)
        .sampled(LS_BINDING_MARCH_COORDINATES, in.coordinates, sm.nearest())
        .sampled(LS_BINDING_MARCH_EPIPOLAR_Z, in.epipolarZ, sm.nearest())
        .sampled(LS_BINDING_MARCH_UV_FRAME, in.sliceUvFrame, sm.nearest())
        .sampledIfValid(LS_BINDING_MARCH_TREES, in.trees, sm.nearest());
    if (in.chain.spec.cubeShadow)
        table.sampled(LS_BINDING_MARCH_END_POINTS, in.sliceEndPoints, sm.nearest());
    addMarchInputs(table, in.chain.shared, in.light);
    const rg::BufferRef counts =
        table.storageBufferReadWriteIfValid(LS_BINDING_MARCH_STEP_COUNTS, in.stepCounts);
    pass.stencilTest(in.marchStencil);
    pass.countSamples();  // the samples marched (FrameReport's PassTime::samples)
    // Stored, not a color attachment: a slot of the march list stores its sample's value at the
    // sample's texel. The second march adds its samples to the first's.
    marched = table.storageWrite(LS_BINDING_MARCH_OUT, marched);
    const uint32_t vertices = cover ? marchCoverVertices(s.marchPhases) : 3;
    pass.execute([frame = in.chain, table, trees, color, counts, marks = options.marks, cover,
                  vertices](rg::PassContext& ctx) {
        const Shared& shared = frame.shared;
        ScatterSpec spec = frame.spec;
        spec.lightColor = color;
        auto desc =
            fullscreenPipeline(rayMarchShader(spec, trees, counts.valid()), ctx, table.layout());
        if (cover) desc.vertex = marchCoverShader();
        desc.specialization = spec.constants();
        desc.stencilTest = true;
        desc.stencil = {VK_STENCIL_OP_KEEP,
                        VK_STENCIL_OP_KEEP,
                        VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_EQUAL,
                        0xff,
                        0,
                        marks};
        const auto& p = shared->pipelines.graphics(
            std::string("ray march") + (counts.valid() ? ", counting" : ""), desc);
        p.bind(ctx.cmd());
        ctx.vk().CmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, marks);
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDraw(ctx.cmd(), vertices, 1, 0, 0);
    });
    return {marched, counts};
}

}  // namespace ls
