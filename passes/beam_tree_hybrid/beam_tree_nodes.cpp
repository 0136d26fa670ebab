#include "beam_tree_nodes.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "beam_tree_shaders.h"
#include "lit_volume_table_frag.h"
#include "planes_frag_variants.h"
#include "shaders/beam_tree_hybrid/beam_tree_bindings.h"
#include "shared/pass_helpers.h"
#include "shared/shader_variant.h"
#include "triangles_vert.h"

namespace ls {

// Bindings only some frames have are build-time variants of the planes' shader; `slab`: the near
// planes' slabs in closed form (planes.frag's LS_SLAB, which reads the point-light table).
rg::ShaderCode beamTreePlanesShader(bool shadowMap, bool cookie, bool cube, bool slab) {
    return pickShader(ls_spirv::planes_frag_variants, {{"LS_SHADOW_MAP", shadowMap},
                                                       {"LS_CUBE_SHADOW", shadowMap && cube},
                                                       {"LS_LIGHT_COLOR", cookie && !cube},
                                                       {"LS_NOISE", 0},
                                                       {"LS_SLAB", slab}});
}

const BeamTreeFrame& beamTreeOf(const LightFrame& frame) {
    return static_cast<const BeamTreeData*>(frame.data)->frame;
}

namespace {

constexpr VkPipelineStageFlags2 kVertexAndFragment =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;

// vkCmdUpdateBuffer takes at most 64 KiB a call. The plugin sizes the buffer from the frame's
// points before it builds the graph (plugin_api/src/plugin.cpp); a frame that does not fit is a bug
// there, and is refused rather than drawn with triangles missing.
void upload(const rg::PassContext& ctx, VkBuffer buffer, const std::vector<glm::vec4>& points,
            size_t capacity) {
    if (points.size() > capacity)
        throw std::logic_error("beam-tree triangles: the frame has " +
                               std::to_string(points.size()) + " points, the buffer holds " +
                               std::to_string(capacity));
    const size_t bytes = points.size() * sizeof(glm::vec4);
    constexpr size_t kChunk = 65536;
    for (size_t offset = 0; offset < bytes; offset += kChunk)
        ctx.vk().CmdUpdateBuffer(ctx.cmd(), buffer, offset, std::min(kChunk, bytes - offset),
                                 reinterpret_cast<const char*>(points.data()) + offset);
}

rg::BufferRef addTriangleUpload(rg::RenderGraph& graph, rg::HostDataRef<LightFrame> values,
                                uint32_t capacityPoints) {
    const VkDeviceSize bytes = VkDeviceSize{capacityPoints} * sizeof(glm::vec4);
    rg::BufferRef triangles = graph.createBuffer("beam-tree triangles", {bytes});
    auto pass = graph.addPass("upload beam-tree triangles (seed 004)", rg::PassType::Transfer);
    triangles = pass.transferDst(triangles);
    const size_t capacity = capacityPoints;
    pass.execute([values, triangles, capacity](rg::PassContext& ctx) {
        upload(ctx, ctx.buffer(triangles), beamTreeOf(ctx.data(values)).points, capacity);
    });
    return triangles;
}

struct PlaneDraw {
    uint32_t first = 0, count = 0;
    bool shadow = false;  // the shadow map is looked up (uncertain space)
    bool near = false;    // planes near the light's depth: thinner, their slabs in closed form
};

// Records sampling-plane triangles [first, first + count) of the uploaded buffer, depth-tested
// against the engine's depth and added to the bound color target.
void drawPlaneParts(rg::PassContext& ctx, const Shared& shared, const ScatterSpec& spec,
                    const BeamTreeFrame& frame, const rg::BindingTable& passTable,
                    const PlaneDraw& draw, bool reversedZ) {
    if (draw.count == 0) return;
    const bool cookie = passTable.has(LS_BINDING_LIGHT_COLOR);
    const rg::BindingTable table =
        draw.shadow ? passTable : passTable.without(LS_BINDING_SHADOW_MAP);
    rg::GraphicsPipelineDesc desc;
    desc.vertex = rg::spirv(ls_spirv::triangles_vert);
    const bool slab = draw.near && passTable.has(LS_BINDING_POINT_TABLE);
    desc.fragment = beamTreePlanesShader(draw.shadow, cookie, spec.cubeShadow, slab);
    desc.formats = ctx.renderingFormats();
    desc.bindings = table.layout();
    desc.pushConstantBytes = sizeof(PlanePush);
    desc.specialization = spec.constants();
    desc.depthTest = true;
    desc.depthCompare = reversedZ ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
    desc.blend = rg::BlendMode::Additive;
    const auto& p = shared->pipelines.graphics("beam-tree planes", desc);
    p.bind(ctx.cmd());
    table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
    PlanePush push = frame.planePush;
    if (draw.near) push.boxMin.w = frame.nearSpacing;  // the slab each near plane stands for
    p.push(ctx.cmd(), push);
    ctx.vk().CmdDraw(ctx.cmd(), draw.count, 1, draw.first, 0);
}

// One group of plane parts (the lit or the uncertain ones, from `first` in the buffer, each plane's
// own from starts[plane]): the planes near the light's depth with their slabs in closed form, the
// others with their midpoints, in draws of their own (a branch per fragment would run both on a
// device that runs a fragment group's both sides, as lavapipe does).
void drawPlaneGroup(rg::PassContext& ctx, const Shared& shared, const ScatterSpec& spec,
                    const BeamTreeFrame& frame, const rg::BindingTable& table, uint32_t first,
                    const std::vector<uint32_t>& starts, bool shadow, bool reversedZ) {
    if (starts.empty()) return;
    const uint32_t planes = static_cast<uint32_t>(starts.size()) - 1;
    const uint32_t a = std::min(frame.nearFirst, planes), b = std::clamp(frame.nearEnd, a, planes);
    auto range = [&](uint32_t from, uint32_t to, bool near) {
        drawPlaneParts(ctx, shared, spec, frame, table,
                       {first + starts[from], starts[to] - starts[from], shadow, near}, reversedZ);
    };
    range(0, a, false);
    range(a, b, true);
    range(b, planes, false);
}

// The plane pass's declarations: the frame's constants, the triangles, the engine's depth as a
// read-only depth attachment, and the shadow map, cookie and point-light table where given.
rg::BindingTable declarePlaneReads(rg::PassBuilder& pass, const ChainContext& chain,
                                   const LightImages& light, rg::BufferRef triangles) {
    const auto& s = samplersOf(chain.shared);
    rg::BindingTable table(pass);
    table.uniform(LS_BINDING_FRAME, chain.constants, kVertexAndFragment)
        .storageBufferRead(LS_BINDING_BEAM_TRIANGLES, triangles,
                           VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT)
        .sampledIfValid(LS_BINDING_SHADOW_MAP, light.shadowMap, s.nearest(),
                        VK_IMAGE_ASPECT_DEPTH_BIT)
        .sampledIfValid(LS_BINDING_LIGHT_COLOR, light.lightColor, s.linear())
        .sampledIfValid(LS_BINDING_POINT_TABLE, light.table, s.nearest());
    pass.depthTest(chain.depth);
    return table;
}

}  // namespace

rg::ImageRef addBeamTreeHybrid(rg::RenderGraph& graph, const BeamTreeInputs& in,
                               const BeamTreeOptions& options) {
    const Shared& shared = in.chain.shared;
    const ScatterSpec& spec = in.chain.spec;
    const rg::HostDataRef<LightFrame> values = in.chain.values;
    const rg::BufferRef triangles = addTriangleUpload(graph, values, options.capacityPoints);
    rg::ImageRef lin = graph.createImage("in-scattering (lit pyramids and uncertain planes)",
                                         rg::ImageDesc::screen(VK_FORMAT_R32G32B32A32_SFLOAT));
    {
        auto pass = graph.addPass("lit pyramids in closed form (seed 004)", rg::PassType::Graphics);
        const auto& s = samplersOf(shared);
        rg::BindingTable table(pass);
        table.uniform(LS_BINDING_FRAME, in.chain.constants, kVertexAndFragment)
            .storageBufferRead(LS_BINDING_BEAM_TRIANGLES, triangles,
                               VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT)
            .sampled(LS_BINDING_DEPTH, in.chain.depth, s.nearest(), VK_IMAGE_ASPECT_DEPTH_BIT)
            .sampled(LS_BINDING_POINT_TABLE, in.light.table, s.nearest());
        lin = pass.colorAttachment(lin, rg::LoadOp::Clear);
        pass.execute([shared, spec, values, table](rg::PassContext& ctx) {
            const uint32_t count = beamTreeOf(ctx.data(values)).litPoints;
            if (count == 0) return;
            rg::GraphicsPipelineDesc desc;
            desc.vertex = rg::spirv(ls_spirv::triangles_vert);
            desc.fragment = rg::spirv(ls_spirv::lit_volume_table_frag);
            desc.formats = ctx.renderingFormats();
            desc.bindings = table.layout();
            desc.specialization = spec.constants();
            desc.specialization.set(LS_SPEC_UNCLIPPED_DEPTH, true);  // no near or far clipping
            desc.blend =
                rg::BlendMode::Additive;  // entries write -E: a float target subtracts them
            const auto& p = shared->pipelines.graphics("lit pyramids", desc);
            p.bind(ctx.cmd());
            table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
            ctx.vk().CmdDraw(ctx.cmd(), count, 1, 0, 0);
        });
    }
    {
        // Without a shadow map (a point light) the uncertain space is sampled as lit: then only the
        // inner boxes cast shadows.
        auto pass = graph.addPass("uncertain sampling planes (seed 004)", rg::PassType::Graphics);
        const rg::BindingTable table = declarePlaneReads(pass, in.chain, in.light, triangles);
        lin = pass.colorAttachment(lin, rg::LoadOp::Load);
        const bool reversedZ = options.reversedZ, shadow = in.light.shadowMap.valid();
        pass.execute([shared, spec, values, shadow, table, reversedZ](rg::PassContext& ctx) {
            const BeamTreeFrame& frame = beamTreeOf(ctx.data(values));
            drawPlaneGroup(ctx, shared, spec, frame, table, frame.litPoints, frame.uncertainStarts,
                           shadow, reversedZ);
        });
    }
    return lin;
}

rg::ImageRef addBeamTreeSampling(rg::RenderGraph& graph, const BeamTreeSamplingInputs& in,
                                 const BeamTreeOptions& options) {
    const Shared& shared = in.chain.shared;
    const ScatterSpec& spec = in.chain.spec;
    const rg::HostDataRef<LightFrame> values = in.chain.values;
    const rg::BufferRef triangles = addTriangleUpload(graph, values, options.capacityPoints);
    rg::ImageRef lin = graph.createImage("in-scattering (lit and uncertain planes)",
                                         rg::ImageDesc::screen(VK_FORMAT_R32G32B32A32_SFLOAT));
    // One pass, two draws: the lit parts skip the shadow map, the uncertain parts look it up.
    auto pass =
        graph.addPass("clipped sampling planes (seed 004 method 1)", rg::PassType::Graphics);
    const rg::BindingTable table = declarePlaneReads(pass, in.chain, in.light, triangles);
    lin = pass.colorAttachment(lin, rg::LoadOp::Clear);
    const bool reversedZ = options.reversedZ, shadow = in.light.shadowMap.valid();
    pass.execute([shared, spec, values, shadow, table, reversedZ](rg::PassContext& ctx) {
        const BeamTreeFrame& frame = beamTreeOf(ctx.data(values));
        drawPlaneGroup(ctx, shared, spec, frame, table, 0, frame.litStarts, false, reversedZ);
        drawPlaneGroup(ctx, shared, spec, frame, table, frame.litPoints, frame.uncertainStarts,
                       shadow, reversedZ);
    });
    return lin;
}

}  // namespace ls
