#include "slice_nodes.h"

#include "shared/pass_helpers.h"
#include "slice_planes_plain_frag.h"
#include "slice_planes_plain_noise_frag.h"
#include "slice_planes_shadowed_color_frag.h"
#include "slice_planes_shadowed_color_noise_frag.h"
#include "slice_planes_shadowed_frag.h"
#include "slice_planes_shadowed_noise_frag.h"
#include "slice_planes_vert.h"
#include "slice_resolve_closed_form_frag.h"
#include "tiling_noise_comp.h"

namespace ls {
namespace {

// Bindings only some frames have are build-time variants (a pipeline never declares a descriptor
// it is not given); the cookie is looked up in the shadow map's space, so it comes with one.
rg::ShaderCode planesShader(bool shadowMap, bool cookie, bool noise) {
    if (!shadowMap)
        return noise ? rg::spirv(ls_spirv::slice_planes_plain_noise_frag)
                     : rg::spirv(ls_spirv::slice_planes_plain_frag);
    if (cookie)
        return noise ? rg::spirv(ls_spirv::slice_planes_shadowed_color_noise_frag)
                     : rg::spirv(ls_spirv::slice_planes_shadowed_color_frag);
    return noise ? rg::spirv(ls_spirv::slice_planes_shadowed_noise_frag)
                 : rg::spirv(ls_spirv::slice_planes_shadowed_frag);
}

VkFormat accumulationFormat(SliceAccumulation target) {
    switch (target) {
        case SliceAccumulation::Float32:
            return VK_FORMAT_R32G32B32A32_SFLOAT;
        case SliceAccumulation::Rgba8Channels:
            return VK_FORMAT_R8G8B8A8_UNORM;
        case SliceAccumulation::Float16:
            break;
    }
    return VK_FORMAT_R16G16B16A16_SFLOAT;
}

}  // namespace

rg::ImageRef addSlicePlanes(rg::RenderGraph& graph, const Shared& shared,
                            SlicePlacementRef placement, const SlicePlanesInputs& in,
                            const SlicePlanesOptions& options) {
    const bool channels = options.target == SliceAccumulation::Rgba8Channels;
    rg::ImageRef sum =
        graph.createImage(channels ? "slice planes' sum (8-bit channels)" : "slice planes' sum",
                          rg::ImageDesc::screen(accumulationFormat(options.target)));
    auto pass = graph.addPass("slice planes (seed 002)", rg::PassType::Graphics);
    pass.uniformBuffer(in.constants, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                                         VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    if (in.shadowMap.valid()) pass.sampled(in.shadowMap, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    if (in.lightColor.valid()) pass.sampled(in.lightColor);
    if (in.noise.valid()) pass.sampled(in.noise);
    pass.depthTest(in.depth);
    sum = pass.colorAttachment(sum, rg::LoadOp::Clear);
    pass.execute([shared, placement, in, options, channels](rg::PassContext& ctx) {
        if (placement->planes == 0) return;  // cleared: the light's volume misses the view
        const ScatterSpec& spec = shared->spec;
        const bool shadow = in.shadowMap.valid(), cookie = in.lightColor.valid(),
                   noise = in.noise.valid();
        rg::GraphicsPipelineDesc desc;
        desc.vertex = rg::spirv(ls_spirv::slice_planes_vert);
        desc.fragment = planesShader(shadow, cookie, noise);
        desc.formats = ctx.renderingFormats();
        desc.bindings = {uniformBinding(0)};
        if (shadow) desc.bindings.push_back(sampledBinding(6));
        if (cookie) desc.bindings.push_back(sampledBinding(8));
        if (noise) desc.bindings.push_back(sampledBinding(9));
        desc.pushConstantBytes = sizeof(SlicePush);
        desc.specialization = spec.constants();
        const bool dither = channels && options.dither;
        desc.specialization.set(10, channels).set(11, dither);
        desc.depthTest = true;
        desc.depthWrite = false;
        // A plane counts where it is in front of the surface.
        desc.depthCompare = options.reversedZ ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
        desc.blend = rg::BlendMode::Additive;
        const std::string variant = spec.key() + (shadow ? "S" : "s") + (cookie ? "C" : "c") +
                                    (noise ? "N" : "n") + (channels ? (dither ? "8d" : "8") : "h") +
                                    (options.reversedZ ? "r" : "f");
        const auto& p = shared->pipelines.graphics(pipelineKey("slice planes", ctx, variant), desc);
        p.bind(ctx.cmd());
        auto set = frameSet(ctx, in.constants);
        const auto& s = shared->samplers;
        if (shadow)
            set.sampled(6, ctx.view(in.shadowMap, VK_IMAGE_ASPECT_DEPTH_BIT),
                        ctx.layout(in.shadowMap), s.nearest());
        if (cookie) set.sampled(8, ctx.view(in.lightColor), ctx.layout(in.lightColor), s.linear());
        if (noise) set.sampled(9, ctx.view(in.noise), ctx.layout(in.noise), s.linearRepeat());
        set.push(ctx.device(), ctx.cmd(), p);
        p.push(ctx.cmd(), placement->push);
        vkCmdDraw(ctx.cmd(), 6, placement->planes, 0, 0);
    });
    return sum;
}

bool sliceResolveNeeded(const SliceResolveOptions& options) {
    return options.target == SliceAccumulation::Rgba8Channels || options.blurRadius > 0 ||
           options.closedFormOutsideSlab;
}

rg::ImageRef addSliceResolve(rg::RenderGraph& graph, const Shared& shared,
                             SlicePlacementRef placement, const SliceResolveInputs& in,
                             const SliceResolveOptions& options) {
    rg::ImageRef lin = graph.createImage("in-scattering (screen)",
                                         rg::ImageDesc::screen(VK_FORMAT_R16G16B16A16_SFLOAT));
    auto pass = graph.addPass("resolve slice planes", rg::PassType::Graphics);
    pass.uniformBuffer(in.constants);
    pass.sampled(in.depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    pass.sampled(in.planeSum);
    lin = pass.colorAttachment(lin, rg::LoadOp::DontCare);
    pass.execute([shared, placement, in, options](rg::PassContext& ctx) {
        const ScatterSpec& spec = shared->spec;
        auto desc = fullscreenPipeline(rg::spirv(ls_spirv::slice_resolve_closed_form_frag), ctx,
                                       {uniformBinding(0), sampledBinding(1), sampledBinding(2)});
        desc.pushConstantBytes = sizeof(SliceResolvePush);
        desc.specialization = spec.constants();
        const bool channels = options.target == SliceAccumulation::Rgba8Channels;
        desc.specialization.set(10, channels)
            .set(11, static_cast<int32_t>(options.blurRadius))
            .set(12, options.closedFormOutsideSlab);
        const std::string variant = spec.key() + (channels ? "8" : "h") + "b" +
                                    std::to_string(options.blurRadius) +
                                    (options.closedFormOutsideSlab ? "o" : "i");
        const auto& p =
            shared->pipelines.graphics(pipelineKey("resolve slice planes", ctx, variant), desc);
        p.bind(ctx.cmd());
        frameSet(ctx, in.constants)
            .sampled(1, ctx.view(in.depth, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.depth), shared->samplers.nearest())
            .sampled(2, ctx.view(in.planeSum), ctx.layout(in.planeSum), shared->samplers.linear())
            .push(ctx.device(), ctx.cmd(), p);
        SliceResolvePush push = placement->resolve;
        if (placement->planes == 0) push.slab = {1e30f, 1e30f, 0.0f, 0.0f};  // all in closed form
        p.push(ctx.cmd(), push);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return lin;
}

rg::ImageRef addTilingNoise(rg::RenderGraph& graph, const Shared& shared, rg::ImageRef noise) {
    auto pass = graph.addPass("tiling noise (seed 002)", rg::PassType::Compute);
    noise = pass.storageWrite(noise);
    pass.execute([shared, noise](rg::PassContext& ctx) {
        const auto& p = shared->pipelines.compute(
            "tiling noise", rg::spirv(ls_spirv::tiling_noise_comp), {storageBinding(0)}, 0, {});
        p.bind(ctx.cmd());
        rg::DescriptorPush set;
        set.storage(0, ctx.view(noise)).push(ctx.device(), ctx.cmd(), p);
        const VkExtent2D e = ctx.extent(noise);
        vkCmdDispatch(ctx.cmd(), groupCount(e.width, 8), groupCount(e.height, 8), 1);
    });
    return noise;
}

}  // namespace ls
