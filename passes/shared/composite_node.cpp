#include "add_inscatter_rgba16f_comp.h"
#include "add_inscatter_rgba16f_out_comp.h"
#include "add_inscatter_rgba32f_comp.h"
#include "add_inscatter_rgba32f_out_comp.h"
#include "pass_helpers.h"
#include "composite_rgba16f_comp.h"
#include "composite_rgba16f_extinction_comp.h"
#include "composite_rgba16f_extinction_out_comp.h"
#include "composite_rgba16f_out_comp.h"
#include "composite_rgba32f_comp.h"
#include "composite_rgba32f_extinction_comp.h"
#include "composite_rgba32f_extinction_out_comp.h"
#include "composite_rgba32f_out_comp.h"
#include "shared_nodes.h"
#include "rendergraph/vk_error.h"

namespace ls {
namespace {

rg::ShaderCode compositeShader(VkFormat color, bool lin, bool out) {
    const bool wide = color == VK_FORMAT_R32G32B32A32_SFLOAT;
    if (!lin) {
        if (wide) return out ? rg::spirv(ls_spirv::composite_rgba32f_extinction_out_comp)
                             : rg::spirv(ls_spirv::composite_rgba32f_extinction_comp);
        return out ? rg::spirv(ls_spirv::composite_rgba16f_extinction_out_comp)
                   : rg::spirv(ls_spirv::composite_rgba16f_extinction_comp);
    }
    if (wide) return out ? rg::spirv(ls_spirv::composite_rgba32f_out_comp)
                         : rg::spirv(ls_spirv::composite_rgba32f_comp);
    return out ? rg::spirv(ls_spirv::composite_rgba16f_out_comp)
               : rg::spirv(ls_spirv::composite_rgba16f_comp);
}

}  // namespace

CompositeOutputs addComposite(rg::RenderGraph& graph, const NodeInputs& in, rg::ImageRef color,
                              rg::ImageRef lin, rg::ImageRef inscatterOut) {
    auto pass = graph.addPass("composite", rg::PassType::Compute);
    pass.uniformBuffer(in.constants);
    pass.sampled(in.depth, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    if (lin.valid()) pass.sampled(lin);
    const rg::ImageRef out = pass.storageReadWrite(color);
    rg::ImageRef linOut;
    if (inscatterOut.valid()) linOut = pass.storageWrite(inscatterOut);
    const VkFormat format = graph.resource(color.id).image.format;
    pass.execute([in, lin, out, linOut, format](rg::PassContext& ctx) {
        std::vector<rg::Binding> b{uniformBinding(0), sampledBinding(1), storageBinding(2)};
        if (lin.valid()) b.push_back(sampledBinding(3));
        if (linOut.valid()) b.push_back(storageBinding(4));
        const std::string key = std::string("composite/") + std::to_string(static_cast<int>(format)) +
                                (lin.valid() ? "/lin" : "") + (linOut.valid() ? "/out" : "");
        const auto& p = in.shared->pipelines.compute(
            key, compositeShader(format, lin.valid(), linOut.valid()), b, 0, {});
        p.bind(ctx.cmd());
        auto set = frameSet(ctx, in.constants);
        set.sampled(1, ctx.view(in.depth, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.depth), in.shared->samplers.nearest())
            .storage(2, ctx.view(out));
        if (lin.valid()) set.sampled(3, ctx.view(lin), ctx.layout(lin), in.shared->samplers.nearest());
        if (linOut.valid()) set.storage(4, ctx.view(linOut));
        set.push(ctx.device(), ctx.cmd(), p);
        const VkExtent2D e = ctx.extent(out);
        vkCmdDispatch(ctx.cmd(), groupCount(e.width, 8), groupCount(e.height, 8), 1);
    });
    return {out, linOut};
}

CompositeOutputs addInscatter(rg::RenderGraph& graph, const NodeInputs& in, rg::ImageRef color, rg::ImageRef lin,
                              rg::ImageRef inscatterOut) {
    auto pass = graph.addPass("add in-scattering", rg::PassType::Compute);
    pass.sampled(lin);
    const rg::ImageRef out = pass.storageReadWrite(color);
    rg::ImageRef linOut;
    if (inscatterOut.valid()) linOut = pass.storageReadWrite(inscatterOut);
    const VkFormat format = graph.resource(color.id).image.format;
    pass.execute([in, lin, out, linOut, format](rg::PassContext& ctx) {
        const bool wide = format == VK_FORMAT_R32G32B32A32_SFLOAT;
        const bool toOut = linOut.valid();
        std::vector<rg::Binding> b{sampledBinding(0), storageBinding(1)};
        if (toOut) b.push_back(storageBinding(2));
        const rg::ShaderCode code = wide ? (toOut ? rg::spirv(ls_spirv::add_inscatter_rgba32f_out_comp)
                                                  : rg::spirv(ls_spirv::add_inscatter_rgba32f_comp))
                                         : (toOut ? rg::spirv(ls_spirv::add_inscatter_rgba16f_out_comp)
                                                  : rg::spirv(ls_spirv::add_inscatter_rgba16f_comp));
        const std::string key = std::string("add in-scattering/") + std::to_string(static_cast<int>(format)) +
                                (toOut ? "/out" : "");
        const auto& p = in.shared->pipelines.compute(key, code, b, 0, {});
        p.bind(ctx.cmd());
        rg::DescriptorPush set;
        set.sampled(0, ctx.view(lin), ctx.layout(lin), in.shared->samplers.nearest()).storage(1, ctx.view(out));
        if (toOut) set.storage(2, ctx.view(linOut));
        set.push(ctx.device(), ctx.cmd(), p);
        const VkExtent2D e = ctx.extent(out);
        vkCmdDispatch(ctx.cmd(), groupCount(e.width, 8), groupCount(e.height, 8), 1);
    });
    return {out, linOut};
}

}  // namespace ls
