#include "composite_target.h"
#include "composite_rgba16f_add_comp.h"
#include "composite_rgba16f_add_out_comp.h"
#include "composite_rgba16f_comp.h"
#include "composite_rgba16f_extinction_comp.h"
#include "composite_rgba16f_extinction_out_comp.h"
#include "composite_rgba16f_out_comp.h"
#include "composite_rgba32f_add_comp.h"
#include "composite_rgba32f_add_out_comp.h"
#include "composite_rgba32f_comp.h"
#include "composite_rgba32f_extinction_comp.h"
#include "composite_rgba32f_extinction_out_comp.h"
#include "composite_rgba32f_out_comp.h"
#include "pass_helpers.h"
#include "shared_nodes.h"

namespace ls {
namespace {

const CompositeVariants kWithLin{rg::spirv(ls_spirv::composite_rgba16f_comp), rg::spirv(ls_spirv::composite_rgba16f_out_comp),
                                 rg::spirv(ls_spirv::composite_rgba32f_comp), rg::spirv(ls_spirv::composite_rgba32f_out_comp)};
const CompositeVariants kExtinctionOnly{
    rg::spirv(ls_spirv::composite_rgba16f_extinction_comp), rg::spirv(ls_spirv::composite_rgba16f_extinction_out_comp),
    rg::spirv(ls_spirv::composite_rgba32f_extinction_comp), rg::spirv(ls_spirv::composite_rgba32f_extinction_out_comp)};
const CompositeVariants kAddOnly{rg::spirv(ls_spirv::composite_rgba16f_add_comp), rg::spirv(ls_spirv::composite_rgba16f_add_out_comp),
                                 rg::spirv(ls_spirv::composite_rgba32f_add_comp), rg::spirv(ls_spirv::composite_rgba32f_add_out_comp)};

CompositeOutputs addCompositePass(rg::RenderGraph& graph, const FrameContext& frame,
                                  const char* name, const CompositeTarget& target,
                                  rg::ImageRef lin) {
    auto pass = graph.addPass(name, rg::PassType::Compute);
    const auto& s = samplersOf(frame.shared);
    rg::BindingTable table = frameTable(pass, frame.constants);
    table.sampled(LS_BINDING_DEPTH, frame.depth, s.nearest(), VK_IMAGE_ASPECT_DEPTH_BIT)
        .sampledIfValid(LS_BINDING_COMPOSITE_LIN, lin, s.nearest());
    const CompositeOutputs written = addCompositeTarget(table, target);
    const CompositeVariants& shaders = target.addOnly ? kAddOnly : lin.valid() ? kWithLin : kExtinctionOnly;
    pass.execute([shared = frame.shared, table, written, &shaders, name](rg::PassContext& ctx) {
        const auto& p =
            shared->pipelines.compute(name, shaders.pick(ctx, written), table.layout(), 0, {});
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        const VkExtent2D e = ctx.extent(written.color);
        vkCmdDispatch(ctx.cmd(), groupCount(e.width, 8), groupCount(e.height, 8), 1);
    });
    return written;
}

}  // namespace

CompositeOutputs addComposite(rg::RenderGraph& graph, const CompositeInputs& in) {
    return addCompositePass(graph, in.frame, "composite", {in.color, in.inscatterOut, false},
                            in.lin);
}

CompositeOutputs addInscatter(rg::RenderGraph& graph, const CompositeInputs& in) {
    return addCompositePass(graph, in.frame, "add in-scattering", {in.color, in.inscatterOut, true},
                            in.lin);
}

}  // namespace ls
