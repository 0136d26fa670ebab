#include "shared/pass_helpers.h"
#include "epipolar_nodes.h"
#include "refine_samples_comp.h"

#include <string>

namespace ls {

rg::ImageRef addRefineSamples(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                              rg::ImageRef epipolarZ) {
    rg::ImageRef sources = g.createImage(
        "interpolation source", rg::ImageDesc::absolute(VK_FORMAT_R16G16_UINT, s.samples, s.slices));
    auto pass = g.addPass("refine sample locations", rg::PassType::Compute);
    pass.uniformBuffer(in.constants);
    pass.sampled(epipolarZ);
    sources = pass.storageWrite(sources);
    pass.execute([in, epipolarZ, sources, s](rg::PassContext& ctx) {
        // The light type only: near a point or spot light the first section is cut geometrically.
        rg::Specialization spec;
        spec.set(0, static_cast<int32_t>(in.shared->spec.light));
        const auto& p = in.shared->pipelines.compute(
            "refine sample locations L" + std::to_string(static_cast<int>(in.shared->spec.light)),
            rg::spirv(ls_spirv::refine_samples_comp),
            {uniformBinding(0), sampledBinding(1), storageBinding(2)}, 0, spec);
        p.bind(ctx.cmd());
        frameSet(ctx, in.constants)
            .sampled(1, ctx.view(epipolarZ), ctx.layout(epipolarZ), in.shared->samplers.nearest())
            .storage(2, ctx.view(sources))
            .push(ctx.device(), ctx.cmd(), p);
        vkCmdDispatch(ctx.cmd(), groupCount(s.samples, 128), s.slices, 1);
    });
    return sources;
}

}  // namespace ls
