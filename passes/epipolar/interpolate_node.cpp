#include "epipolar_nodes.h"
#include "interpolate_frag.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"

namespace ls {

rg::ImageRef addInterpolate(rg::RenderGraph& g, const InterpolateInputs& in,
                            const EpipolarSizes& s) {
    rg::ImageRef interpolated =
        g.createImage("in-scattering (all samples)",
                      rg::ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, s.samples, s.slices));
    auto pass = g.addPass("interpolate in-scattering", rg::PassType::Graphics);
    const auto& sm = samplersOf(in.chain.shared);
    rg::BindingTable table = epipolarTable(pass, in.chain, in.epipolar);
    table.sampled(LS_BINDING_INTERPOLATION_SOURCE, in.interpolationSource, sm.nearest())
        .sampled(LS_BINDING_INTERPOLATE_MARCHED, in.marched, sm.nearest())
        .sampled(LS_BINDING_SOURCES_EPIPOLAR_Z, in.epipolarZ, sm.nearest());
    interpolated = pass.colorAttachment(interpolated, rg::LoadOp::Clear);
    pass.execute([shared = in.chain.shared, table](rg::PassContext& ctx) {
        auto desc = fullscreenPipeline(rg::spirv(ls_spirv::interpolate_frag), ctx, table.layout());
        const auto& p = shared->pipelines.graphics("interpolate in-scattering", desc);
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return interpolated;
}

}  // namespace ls
