#include "composite_apply_comp_variants.h"
#include "composite_blend_frag_variants.h"
#include "pass_helpers.h"
#include "shader_variant.h"
#include "shared_nodes.h"
#include "shared_shaders.h"
#include "transmittance_export_comp_variants.h"

namespace ls {

rg::ShaderCode compositeBlendShader(bool dualSource) {
    return pickShader(ls_spirv::composite_blend_frag_variants, {{"LS_DUAL_SOURCE", dualSource}});
}

rg::ShaderCode compositeApplyShader(VkFormat color) {
    return pickShader(ls_spirv::composite_apply_comp_variants,
                      {{"LS_COLOR_RGBA32F", color == VK_FORMAT_R32G32B32A32_SFLOAT}});
}

rg::ShaderCode transmittanceExportShader(VkFormat out) {
    return pickShader(ls_spirv::transmittance_export_comp_variants,
                      {{"LS_OUT_RGBA32F", out == VK_FORMAT_R32G32B32A32_SFLOAT}});
}

namespace {

struct SizePush {
    int32_t width, height;
};

// A compute pass over the frame's pixels that reads the split images and writes `target` (the
// engine's storage image) with `shader`; returns its new version.
rg::ImageRef addSplitCompute(rg::RenderGraph& graph, const ChainContext& chain, const char* name,
                             rg::ImageRef lin, rg::ImageRef transmittance, rg::ImageRef target,
                             bool readsTarget, rg::ShaderCode (*shader)(VkFormat)) {
    auto pass = graph.addPass(name, rg::PassType::Compute);
    const auto& s = samplersOf(chain.shared);
    rg::BindingTable table(pass);
    table.sampledIfValid(LS_BINDING_SPLIT_LIN, lin, s.nearest())
        .sampled(LS_BINDING_SPLIT_T, transmittance, s.nearest());
    const rg::ImageRef written = readsTarget
                                     ? table.storageReadWrite(LS_BINDING_SPLIT_TARGET, target)
                                     : table.storageWrite(LS_BINDING_SPLIT_TARGET, target);
    pass.execute([shared = chain.shared, table, written, shader, name](rg::PassContext& ctx) {
        const auto& p = shared->pipelines.compute(name, shader(ctx.format(written)), table.layout(),
                                                  sizeof(SizePush), {});
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        // The frame's extent: under dynamic resolution the engine's image is larger.
        const VkExtent2D e = ctx.extent(written);
        p.push(ctx.cmd(), SizePush{int32_t(e.width), int32_t(e.height)});
        ctx.vk().CmdDispatch(ctx.cmd(), groupCount(e.width, 8), groupCount(e.height, 8), 1);
    });
    return written;
}

}  // namespace

rg::ImageRef addSplitComposite(rg::RenderGraph& graph, const SplitCompositeInputs& in) {
    if (in.storage)
        return addSplitCompute(graph, in.chain, "composite into color (storage)", in.lin,
                               in.transmittance, in.color, true, compositeApplyShader);
    // Named for how it blends, which the frame's report then says.
    auto pass = graph.addPass(in.dualSource ? "composite into color (dual-source blend)"
                                            : "composite into color (two blended draws)",
                              rg::PassType::Graphics);
    const auto& s = samplersOf(in.chain.shared);
    rg::BindingTable table(pass);
    table.sampled(LS_BINDING_SPLIT_LIN, in.lin, s.nearest())
        .sampled(LS_BINDING_SPLIT_T, in.transmittance, s.nearest());
    const rg::ImageRef written = pass.colorAttachment(in.color, rg::LoadOp::Load);
    pass.execute([shared = in.chain.shared, table, dual = in.dualSource](rg::PassContext& ctx) {
        auto desc = fullscreenPipeline(compositeBlendShader(dual), ctx, table.layout());
        if (dual) {
            desc.blend = rg::BlendMode::DualSourceMultiplyAdd;
            const auto& p = shared->pipelines.graphics("composite into color", desc);
            p.bind(ctx.cmd());
            table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
            ctx.vk().CmdDraw(ctx.cmd(), 3, 1, 0, 0);
            return;
        }
        // Without dual-source blending: multiply by T, then add k Lin (blending is in draw order).
        desc.pushConstantBytes = sizeof(uint32_t);
        desc.blend = rg::BlendMode::Multiply;
        const auto& multiply = shared->pipelines.graphics("composite into color: multiply", desc);
        desc.blend = rg::BlendMode::Additive;
        const auto& add = shared->pipelines.graphics("composite into color: add", desc);
        for (uint32_t addLin : {0u, 1u}) {
            const rg::Pipeline& p = addLin ? add : multiply;
            p.bind(ctx.cmd());
            table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
            p.push(ctx.cmd(), addLin);
            ctx.vk().CmdDraw(ctx.cmd(), 3, 1, 0, 0);
        }
    });
    return written;
}

rg::ImageRef addTransmittanceExport(rg::RenderGraph& graph, const TransmittanceExportInputs& in) {
    return addSplitCompute(graph, in.chain, "transmittance export", {}, in.transmittance, in.out,
                           false, transmittanceExportShader);
}

}  // namespace ls
