#include "beam_tree_nodes.h"

#include <algorithm>

#include "lit_volume_table_frag.h"
#include "shared/pass_helpers.h"
#include "slice_planes_plain_frag.h"
#include "slice_planes_shadowed_color_frag.h"
#include "slice_planes_shadowed_frag.h"
#include "triangles_vert.h"

namespace ls {
namespace {

rg::Binding storageBufferBinding(uint32_t binding) {
    return {binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_ALL};
}

// vkCmdUpdateBuffer takes at most 64 KiB a call.
void upload(VkCommandBuffer cmd, VkBuffer buffer, const std::vector<glm::vec4>& points,
            size_t capacity) {
    const size_t bytes = std::min(points.size(), capacity) * sizeof(glm::vec4);
    constexpr size_t kChunk = 65536;
    for (size_t offset = 0; offset < bytes; offset += kChunk)
        vkCmdUpdateBuffer(cmd, buffer, offset, std::min(kChunk, bytes - offset),
                          reinterpret_cast<const char*>(points.data()) + offset);
}

}  // namespace

rg::ImageRef addBeamTreeHybrid(rg::RenderGraph& graph, const Shared& shared, BeamTreeFrameRef frame,
                               const BeamTreeInputs& in, const BeamTreeOptions& options) {
    const VkDeviceSize bytes = VkDeviceSize{options.capacityPoints} * sizeof(glm::vec4);
    rg::BufferRef triangles = graph.createBuffer("beam-tree triangles", {bytes});
    {
        auto pass = graph.addPass("upload beam-tree triangles (seed 004)", rg::PassType::Transfer);
        triangles = pass.transferDst(triangles);
        const size_t capacity = options.capacityPoints;
        pass.execute([frame, triangles, capacity](rg::PassContext& ctx) {
            upload(ctx.cmd(), ctx.buffer(triangles), frame->points, capacity);
        });
    }
    rg::ImageRef lin = graph.createImage("in-scattering (lit pyramids and uncertain planes)",
                                         rg::ImageDesc::screen(VK_FORMAT_R32G32B32A32_SFLOAT));
    const VkPipelineStageFlags2 both =
        VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    {
        auto pass = graph.addPass("lit pyramids in closed form (seed 004)", rg::PassType::Graphics);
        pass.uniformBuffer(in.constants, both);
        pass.storageBufferRead(triangles, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
        pass.sampled(in.cameraZ);
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
                .sampled(1, ctx.view(in.cameraZ), ctx.layout(in.cameraZ),
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
        pass.uniformBuffer(in.constants, both);
        pass.storageBufferRead(triangles, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
        if (in.shadowMap.valid()) pass.sampled(in.shadowMap, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
        if (in.lightColor.valid()) pass.sampled(in.lightColor);
        pass.depthTest(in.depth);
        lin = pass.colorAttachment(lin, rg::LoadOp::Load);
        const bool reversedZ = options.reversedZ;
        pass.execute([shared, frame, in, triangles, reversedZ](rg::PassContext& ctx) {
            const uint32_t count = frame->uncertainPoints;
            if (count == 0) return;
            const bool cookie = in.lightColor.valid(), shadow = in.shadowMap.valid();
            rg::GraphicsPipelineDesc desc;
            desc.vertex = rg::spirv(ls_spirv::triangles_vert);
            desc.fragment = !shadow  ? rg::spirv(ls_spirv::slice_planes_plain_frag)
                            : cookie ? rg::spirv(ls_spirv::slice_planes_shadowed_color_frag)
                                     : rg::spirv(ls_spirv::slice_planes_shadowed_frag);
            desc.formats = ctx.renderingFormats();
            desc.bindings = {uniformBinding(0), storageBufferBinding(3)};
            if (shadow) desc.bindings.push_back(sampledBinding(6));
            if (cookie) desc.bindings.push_back(sampledBinding(8));
            desc.pushConstantBytes = sizeof(SlicePush);
            desc.specialization = shared->spec.constants();
            desc.depthTest = true;
            desc.depthCompare = reversedZ ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
            desc.blend = rg::BlendMode::Additive;
            const auto& p = shared->pipelines.graphics(
                pipelineKey("uncertain planes", ctx,
                            shared->spec.key() + (shadow ? "S" : "s") + (cookie ? "C" : "c") +
                                (reversedZ ? "r" : "f")),
                desc);
            p.bind(ctx.cmd());
            auto set = frameSet(ctx, in.constants);
            set.storageBuffer(3, ctx.buffer(triangles));
            if (shadow)
                set.sampled(6, ctx.view(in.shadowMap, VK_IMAGE_ASPECT_DEPTH_BIT),
                            ctx.layout(in.shadowMap), shared->samplers.nearest());
            if (cookie)
                set.sampled(8, ctx.view(in.lightColor), ctx.layout(in.lightColor),
                            shared->samplers.linear());
            set.push(ctx.device(), ctx.cmd(), p);
            p.push(ctx.cmd(), frame->slicePush);
            vkCmdDraw(ctx.cmd(), count, 1, frame->litPoints, 0);
        });
    }
    return lin;
}

}  // namespace ls
