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

CompositeOutputs addCompositePass(rg::RenderGraph& graph, const NodeInputs& in, const char* name,
                                  const CompositeTarget& target, rg::ImageRef lin) {
    auto pass = graph.addPass(name, rg::PassType::Compute);
    pass.uniformBuffer(in.constants);
    pass.sampled(in.depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    if (lin.valid()) pass.sampled(lin);
    const CompositeOutputs written = declareCompositeTarget(pass, target);
    const CompositeVariants& shaders = target.addOnly ? kAddOnly : lin.valid() ? kWithLin : kExtinctionOnly;
    pass.execute([in, lin, written, &shaders, name](rg::PassContext& ctx) {
        std::vector<rg::Binding> b{uniformBinding(0), sampledBinding(1)};
        if (lin.valid()) b.push_back(sampledBinding(3));
        appendCompositeBindings(b, written);
        const std::string key = std::string(name) + "/" + compositeKey(ctx, written) + (lin.valid() ? "/lin" : "");
        const auto& p = in.shared->pipelines.compute(key, shaders.pick(ctx, written), b, 0, {});
        p.bind(ctx.cmd());
        auto set = frameSet(ctx, in.constants);
        set.sampled(1, ctx.view(in.depth, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.depth), in.shared->samplers.nearest());
        if (lin.valid()) set.sampled(3, ctx.view(lin), ctx.layout(lin), in.shared->samplers.nearest());
        pushCompositeTarget(set, ctx, written);
        set.push(ctx.device(), ctx.cmd(), p);
        const VkExtent2D e = ctx.extent(written.color);
        vkCmdDispatch(ctx.cmd(), groupCount(e.width, 8), groupCount(e.height, 8), 1);
    });
    return written;
}

}  // namespace

CompositeOutputs addComposite(rg::RenderGraph& graph, const NodeInputs& in, rg::ImageRef color,
                              rg::ImageRef lin, rg::ImageRef inscatterOut) {
    return addCompositePass(graph, in, "composite", {color, inscatterOut, false}, lin);
}

CompositeOutputs addInscatter(rg::RenderGraph& graph, const NodeInputs& in, rg::ImageRef color, rg::ImageRef lin,
                              rg::ImageRef inscatterOut) {
    return addCompositePass(graph, in, "add in-scattering", {color, inscatterOut, true}, lin);
}

}  // namespace ls
