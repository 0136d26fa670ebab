#include "plane_nodes.h"

#include "plane_resolve_closed_form_frag.h"
#include "plane_shaders.h"
#include "planes_frag_variants.h"
#include "planes_vert.h"
#include "shaders/planes/planes_bindings.h"
#include "shared/pass_helpers.h"
#include "shared/shader_variant.h"

namespace ls {

// Bindings only some frames have are build-time variants (a pipeline never declares a descriptor
// it is not given); the cookie is looked up in the light's projection, with a shadow map or not.
// A point light's cube map (`cube`, with a shadow map) comes without light color (refused with it).
rg::ShaderCode planesShader(bool shadowMap, bool cookie, bool noise, bool cube) {
    return pickShader(ls_spirv::planes_frag_variants,
                      {{"LS_SHADOW_MAP", shadowMap},
                       {"LS_CUBE_SHADOW", shadowMap && cube},
                       {"LS_LIGHT_COLOR", cookie && !(shadowMap && cube)},
                       {"LS_NOISE", noise},
                       {"LS_SLAB", 0}});
}

const PlanePlacement& placementOf(const LightFrame& frame) {
    return static_cast<const PlaneData*>(frame.data)->placement;
}

namespace {

VkFormat accumulationFormat(PlaneTarget target) {
    switch (target) {
        case PlaneTarget::Float32:
            return VK_FORMAT_R32G32B32A32_SFLOAT;
        case PlaneTarget::Rgba8Channels:
            return VK_FORMAT_R8G8B8A8_UNORM;
        case PlaneTarget::Float16:
            break;
    }
    return VK_FORMAT_R16G16B16A16_SFLOAT;
}

}  // namespace

rg::ImageRef addPlanes(rg::RenderGraph& graph, const PlanesInputs& in,
                       const PlanesOptions& options) {
    const Shared& shared = in.chain.shared;
    const bool channels = options.target == PlaneTarget::Rgba8Channels;
    rg::ImageRef sum = graph.createImage(channels ? "planes' sum (8-bit channels)" : "planes' sum",
                                         rg::ImageDesc::screen(accumulationFormat(options.target)));
    auto pass = graph.addPass("planes (seed 002)", rg::PassType::Graphics);
    const auto& s = samplersOf(shared);
    rg::BindingTable table(pass);
    table
        .uniform(LS_BINDING_FRAME, in.chain.constants,
                 VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT)
        .sampledIfValid(LS_BINDING_SHADOW_MAP, in.light.shadowMap, s.nearest(),
                        VK_IMAGE_ASPECT_DEPTH_BIT)
        .sampledIfValid(LS_BINDING_LIGHT_COLOR, in.light.lightColor, s.linear())
        .sampledIfValid(LS_BINDING_NOISE, in.noise, s.linearRepeat());
    pass.depthTest(in.chain.depth);
    sum = pass.colorAttachment(sum, rg::LoadOp::Clear);
    pass.execute(
        [shared, spec = in.chain.spec, table, in, options, channels](rg::PassContext& ctx) {
            const PlanePlacement& placement = placementOf(ctx.data(in.chain.values));
            if (placement.planes == 0) return;  // cleared: the light's volume misses the view
            const bool shadow = in.light.shadowMap.valid(), cookie = in.light.lightColor.valid(),
                       noise = in.noise.valid();
            rg::GraphicsPipelineDesc desc;
            desc.vertex = rg::spirv(ls_spirv::planes_vert);
            desc.fragment = planesShader(shadow, cookie, noise, spec.cubeShadow);
            desc.formats = ctx.renderingFormats();
            desc.bindings = table.layout();
            desc.pushConstantBytes = sizeof(PlanePush);
            desc.specialization = spec.constants();
            const bool dither = channels && options.dither;
            desc.specialization.set(LS_SPEC_PLANES_CHANNELS, channels)
                .set(LS_SPEC_PLANES_DITHER, dither);
            desc.depthTest = true;
            desc.depthWrite = false;
            // A plane counts where it is in front of the surface.
            desc.depthCompare = options.reversedZ ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
            desc.blend = rg::BlendMode::Additive;
            const auto& p = shared->pipelines.graphics("planes", desc);
            p.bind(ctx.cmd());
            table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
            p.push(ctx.cmd(), placement.push);
            ctx.vk().CmdDraw(ctx.cmd(), 6, placement.planes, 0, 0);
        });
    return sum;
}

bool planeResolveNeeded(const PlaneResolveOptions& options) {
    return options.target == PlaneTarget::Rgba8Channels || options.blurRadius > 0 ||
           options.closedFormOutsideSlab;
}

rg::ImageRef addPlaneResolve(rg::RenderGraph& graph, const PlaneResolveInputs& in,
                             const PlaneResolveOptions& options) {
    const Shared& shared = in.chain.shared;
    rg::ImageRef lin = graph.createImage("in-scattering (screen)",
                                         rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    auto pass = graph.addPass("resolve planes", rg::PassType::Graphics);
    rg::BindingTable table = frameTable(pass, in.chain.constants);
    table
        .sampled(LS_BINDING_DEPTH, in.chain.depth, samplersOf(shared).nearest(),
                 VK_IMAGE_ASPECT_DEPTH_BIT)
        .sampled(LS_BINDING_PLANE_SUM, in.planeSum, samplersOf(shared).linear());
    lin = pass.colorAttachment(lin, rg::LoadOp::DontCare);
    pass.execute([shared, spec = in.chain.spec, values = in.chain.values, table,
                  options](rg::PassContext& ctx) {
        auto desc = fullscreenPipeline(rg::spirv(ls_spirv::plane_resolve_closed_form_frag), ctx,
                                       table.layout());
        desc.pushConstantBytes = sizeof(PlaneResolvePush);
        desc.specialization = spec.constants();
        const bool channels = options.target == PlaneTarget::Rgba8Channels;
        desc.specialization.set(LS_SPEC_RESOLVE_CHANNELS, channels)
            .set(LS_SPEC_RESOLVE_BLUR_RADIUS, static_cast<int32_t>(options.blurRadius))
            .set(LS_SPEC_RESOLVE_CLOSED_FORM_OUTSIDE_SLAB, options.closedFormOutsideSlab);
        const auto& p = shared->pipelines.graphics("resolve planes", desc);
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        const PlanePlacement& placement = placementOf(ctx.data(values));
        PlaneResolvePush push = placement.resolve;
        if (placement.planes == 0) push.slab = {1e30f, 1e30f, 0.0f, 0.0f};  // all in closed form
        p.push(ctx.cmd(), push);
        ctx.vk().CmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return lin;
}

}  // namespace ls
