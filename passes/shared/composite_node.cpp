#include "composite_comp_variants.h"
#include "composite_target.h"
#include "pass_helpers.h"
#include "shader_variant.h"
#include "shared_nodes.h"
#include "shared_shaders.h"

namespace ls {

rg::ShaderCode compositeShader(bool addOnly, bool withLin, const CompositeVariant& target) {
    return pickCompositeShader(ls_spirv::composite_comp_variants,
                               {{"LS_WITH_LIN", withLin || addOnly}, {"LS_ADD_ONLY", addOnly}},
                               target);
}

namespace {

CompositeOutputs addCompositePass(rg::RenderGraph& graph, const ChainContext& chain,
                                  const char* name, const CompositeTarget& target,
                                  rg::ImageRef lin) {
    auto pass = graph.addPass(name, rg::PassType::Compute);
    const auto& s = samplersOf(chain.shared);
    rg::BindingTable table = frameTable(pass, chain.constants);
    table.sampled(LS_BINDING_DEPTH, chain.depth, s.nearest(), VK_IMAGE_ASPECT_DEPTH_BIT)
        .sampledIfValid(LS_BINDING_COMPOSITE_LIN, lin, s.nearest());
    const CompositeOutputs written = addCompositeTarget(table, target);
    const bool addOnly = target.addOnly, withLin = lin.valid();
    pass.execute([shared = chain.shared, media = chain.spec.mediaConstants(), table, written,
                  addOnly, withLin, name](rg::PassContext& ctx) {
        const rg::ShaderCode shader =
            compositeShader(addOnly, withLin, compositeVariant(ctx, written));
        const auto& p = shared->pipelines.compute(name, shader, table.layout(), 0, media);
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        const VkExtent2D e = ctx.extent(written.color);
        ctx.vk().CmdDispatch(ctx.cmd(), groupCount(e.width, 8), groupCount(e.height, 8), 1);
    });
    return written;
}

}  // namespace

CompositeOutputs addComposite(rg::RenderGraph& graph, const CompositeInputs& in) {
    return addCompositePass(graph, in.chain, "composite",
                            {in.color, in.inscatterOut, false, in.transmittance}, in.lin);
}

CompositeOutputs addInscatter(rg::RenderGraph& graph, const CompositeInputs& in) {
    return addCompositePass(graph, in.chain, "add in-scattering",
                            {in.color, in.inscatterOut, true, in.transmittance}, in.lin);
}

}  // namespace ls
