#include "epipolar_nodes.h"
#include "refine_samples_comp.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"

#include <string>

namespace ls {

RefinedSamples addRefineSamples(rg::RenderGraph& g, const RefineSamplesInputs& in,
                                const EpipolarSizes& s) {
    rg::ImageRef sources =
        g.createImage("interpolation source",
                      rg::ImageDesc::absolute(VK_FORMAT_R16G16_UINT, s.samples, s.slices));
    auto pass = g.addPass("refine sample locations", rg::PassType::Compute);
    rg::BindingTable table = epipolarTable(pass, in.chain, in.epipolar);
    table.sampled(LS_BINDING_REFINE_EPIPOLAR_Z, in.epipolarZ,
                  samplersOf(in.chain.shared).nearest());
    sources = table.storageWrite(LS_BINDING_REFINE_SOURCES, sources);
    const rg::BufferRef list = table.storageBufferReadWrite(LS_BINDING_REFINE_LIST, in.marchList);
    pass.execute(
        [shared = in.chain.shared, light = in.chain.spec.light, table, s](rg::PassContext& ctx) {
            // The light type only: near a point or spot light the first section is cut
            // geometrically.
            rg::Specialization spec;
            spec.set(LS_SPEC_LIGHT_TYPE, static_cast<int32_t>(light));
            const auto& p = shared->pipelines.compute("refine sample locations",
                                                      rg::spirv(ls_spirv::refine_samples_comp),
                                                      table.layout(), 0, spec);
            p.bind(ctx.cmd());
            table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
            ctx.vk().CmdDispatch(ctx.cmd(), groupCount(s.samples, 128), s.slices, 1);
        });
    return {sources, list};
}

}  // namespace ls
