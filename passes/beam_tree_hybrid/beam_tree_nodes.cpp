#include "beam_tree_nodes.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "lit_volume_table_frag.h"
#include "shared/pass_helpers.h"
#include "slice_planes_color_frag.h"
#include "slice_planes_plain_frag.h"
#include "slice_planes_shadowed_color_frag.h"
#include "slice_planes_shadowed_frag.h"
#include "triangles_vert.h"

namespace ls {
namespace {

constexpr VkPipelineStageFlags2 kVertexAndFragment =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;

// vkCmdUpdateBuffer takes at most 64 KiB a call. The plugin sizes the buffer from the frame's
// points before it builds the graph (plugin_api/plugin.cpp); a frame that does not fit is a bug
// there, and is refused rather than drawn with triangles missing.
void upload(VkCommandBuffer cmd, VkBuffer buffer, const std::vector<glm::vec4>& points,
            size_t capacity) {
    if (points.size() > capacity)
        throw std::logic_error("beam-tree triangles: the frame has " +
                               std::to_string(points.size()) + " points, the buffer holds " +
                               std::to_string(capacity));
    const size_t bytes = points.size() * sizeof(glm::vec4);
    constexpr size_t kChunk = 65536;
    for (size_t offset = 0; offset < bytes; offset += kChunk)
        vkCmdUpdateBuffer(cmd, buffer, offset, std::min(kChunk, bytes - offset),
                          reinterpret_cast<const char*>(points.data()) + offset);
}

rg::BufferRef addTriangleUpload(rg::RenderGraph& graph, BeamTreeFrameRef frame,
                                uint32_t capacityPoints) {
    const VkDeviceSize bytes = VkDeviceSize{capacityPoints} * sizeof(glm::vec4);
    rg::BufferRef triangles = graph.createBuffer("beam-tree triangles", {bytes});
    auto pass = graph.addPass("upload beam-tree triangles (seed 004)", rg::PassType::Transfer);
    triangles = pass.transferDst(triangles);
    const size_t capacity = capacityPoints;
    pass.execute([frame, triangles, capacity](rg::PassContext& ctx) {
        upload(ctx.cmd(), ctx.buffer(triangles), frame->points, capacity);
    });
    return triangles;
}

// Bindings only some frames have are build-time variants of the planes' shader.
rg::ShaderCode planesShader(bool shadowMap, bool cookie) {
    if (shadowMap)
        return cookie ? rg::spirv(ls_spirv::slice_planes_shadowed_color_frag)
                      : rg::spirv(ls_spirv::slice_planes_shadowed_frag);
    return cookie ? rg::spirv(ls_spirv::slice_planes_color_frag)
                  : rg::spirv(ls_spirv::slice_planes_plain_frag);
}

struct PlaneDraw {
    uint32_t first = 0, count = 0;
    bool shadow = false;  // the shadow map is looked up (uncertain space)
};

// Records sampling-plane triangles [first, first + count) of the uploaded buffer, depth-tested
// against the engine's depth and added to the bound color target.
void drawPlaneParts(rg::PassContext& ctx, const Shared& shared, const BeamTreeFrame& frame,
                    rg::BufferRef constants, rg::ImageRef shadowMap, rg::ImageRef lightColor,
                    rg::BufferRef triangles, const PlaneDraw& draw, bool reversedZ) {
    if (draw.count == 0) return;
    const bool cookie = lightColor.valid();
    rg::GraphicsPipelineDesc desc;
    desc.vertex = rg::spirv(ls_spirv::triangles_vert);
    desc.fragment = planesShader(draw.shadow, cookie);
    desc.formats = ctx.renderingFormats();
    desc.bindings = {uniformBinding(0), storageBufferBinding(3)};
    if (draw.shadow) desc.bindings.push_back(sampledBinding(6));
    if (cookie) desc.bindings.push_back(sampledBinding(8));
    desc.pushConstantBytes = sizeof(SlicePush);
    desc.specialization = shared->spec.constants();
    desc.depthTest = true;
    desc.depthCompare = reversedZ ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
    desc.blend = rg::BlendMode::Additive;
    const auto& p =
        shared->pipelines.graphics(pipelineKey("beam-tree planes", ctx,
                                               shared->spec.key() + (draw.shadow ? "S" : "s") +
                                                   (cookie ? "C" : "c") + (reversedZ ? "r" : "f")),
                                   desc);
    p.bind(ctx.cmd());
    auto set = frameSet(ctx, constants);
    set.storageBuffer(3, ctx.buffer(triangles));
    if (draw.shadow)
        set.sampled(6, ctx.view(shadowMap, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(shadowMap),
                    shared->samplers.nearest());
    if (cookie)
        set.sampled(8, ctx.view(lightColor), ctx.layout(lightColor), shared->samplers.linear());
    set.push(ctx.device(), ctx.cmd(), p);
    p.push(ctx.cmd(), frame.slicePush);
    vkCmdDraw(ctx.cmd(), draw.count, 1, draw.first, 0);
}

// The plane pass's declarations: the frame's constants, the triangles, the engine's depth as a
// read-only depth attachment, and the shadow map and cookie where given.
void declarePlaneReads(rg::PassBuilder& pass, rg::BufferRef constants, rg::BufferRef triangles,
                       rg::ImageRef depth, rg::ImageRef shadowMap, rg::ImageRef lightColor) {
    pass.uniformBuffer(constants, kVertexAndFragment);
    pass.storageBufferRead(triangles, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
    if (shadowMap.valid()) pass.sampled(shadowMap, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    if (lightColor.valid()) pass.sampled(lightColor);
    pass.depthTest(depth);
}

}  // namespace

rg::ImageRef addBeamTreeHybrid(rg::RenderGraph& graph, const Shared& shared, BeamTreeFrameRef frame,
                               const BeamTreeInputs& in, const BeamTreeOptions& options) {
    const rg::BufferRef triangles = addTriangleUpload(graph, frame, options.capacityPoints);
    rg::ImageRef lin = graph.createImage("in-scattering (lit pyramids and uncertain planes)",
                                         rg::ImageDesc::screen(VK_FORMAT_R32G32B32A32_SFLOAT));
    {
        auto pass = graph.addPass("lit pyramids in closed form (seed 004)", rg::PassType::Graphics);
        pass.uniformBuffer(in.constants, kVertexAndFragment);
        pass.storageBufferRead(triangles, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
        pass.sampled(in.depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
        pass.sampled(in.table);
        lin = pass.colorAttachment(lin, rg::LoadOp::Clear);
        pass.execute([shared, frame, in, triangles](rg::PassContext& ctx) {
            const uint32_t count = frame->litPoints;
            if (count == 0) return;
            rg::GraphicsPipelineDesc desc;
            desc.vertex = rg::spirv(ls_spirv::triangles_vert);
            desc.fragment = rg::spirv(ls_spirv::lit_volume_table_frag);
            desc.formats = ctx.renderingFormats();
            desc.bindings = {uniformBinding(0), sampledBinding(1), storageBufferBinding(3),
                             sampledBinding(7)};
            desc.specialization = shared->spec.constants();
            desc.specialization.set(20, true);  // triangles.vert: no near or far clipping
            desc.blend =
                rg::BlendMode::Additive;  // entries write -E: a float target subtracts them
            const auto& p = shared->pipelines.graphics(
                pipelineKey("lit pyramids", ctx, shared->spec.key()), desc);
            p.bind(ctx.cmd());
            frameSet(ctx, in.constants)
                .sampled(1, ctx.view(in.depth, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.depth),
                         shared->samplers.nearest())
                .storageBuffer(3, ctx.buffer(triangles))
                .sampled(7, ctx.view(in.table), ctx.layout(in.table), shared->samplers.nearest())
                .push(ctx.device(), ctx.cmd(), p);
            vkCmdDraw(ctx.cmd(), count, 1, 0, 0);
        });
    }
    {
        // Without a shadow map (a point light) the uncertain space is sampled as lit: then only the
        // inner boxes cast shadows.
        auto pass = graph.addPass("uncertain sampling planes (seed 004)", rg::PassType::Graphics);
        declarePlaneReads(pass, in.constants, triangles, in.depth, in.shadowMap, in.lightColor);
        lin = pass.colorAttachment(lin, rg::LoadOp::Load);
        const bool reversedZ = options.reversedZ;
        pass.execute([shared, frame, in, triangles, reversedZ](rg::PassContext& ctx) {
            const PlaneDraw uncertain{frame->litPoints, frame->uncertainPoints,
                                      in.shadowMap.valid()};
            drawPlaneParts(ctx, shared, *frame, in.constants, in.shadowMap, in.lightColor,
                           triangles, uncertain, reversedZ);
        });
    }
    return lin;
}

rg::ImageRef addBeamTreeSampling(rg::RenderGraph& graph, const Shared& shared,
                                 BeamTreeFrameRef frame, const BeamTreeSamplingInputs& in,
                                 const BeamTreeOptions& options) {
    const rg::BufferRef triangles = addTriangleUpload(graph, frame, options.capacityPoints);
    rg::ImageRef lin = graph.createImage("in-scattering (lit and uncertain planes)",
                                         rg::ImageDesc::screen(VK_FORMAT_R32G32B32A32_SFLOAT));
    // One pass, two draws: the lit parts skip the shadow map, the uncertain parts look it up.
    auto pass =
        graph.addPass("clipped sampling planes (seed 004 method 1)", rg::PassType::Graphics);
    declarePlaneReads(pass, in.constants, triangles, in.depth, in.shadowMap, in.lightColor);
    lin = pass.colorAttachment(lin, rg::LoadOp::Clear);
    const bool reversedZ = options.reversedZ;
    pass.execute([shared, frame, in, triangles, reversedZ](rg::PassContext& ctx) {
        const PlaneDraw lit{0, frame->litPoints, false};
        const PlaneDraw uncertain{frame->litPoints, frame->uncertainPoints, in.shadowMap.valid()};
        drawPlaneParts(ctx, shared, *frame, in.constants, in.shadowMap, in.lightColor, triangles,
                       lit, reversedZ);
        drawPlaneParts(ctx, shared, *frame, in.constants, in.shadowMap, in.lightColor, triangles,
                       uncertain, reversedZ);
    });
    return lin;
}

}  // namespace ls
