#include "epipolar_coordinates_frag.h"
#include "epipolar_nodes.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"

namespace ls {

EpipolarCoordinates addEpipolarCoordinates(rg::RenderGraph& g, const EpipolarCoordinatesInputs& in,
                                           const EpipolarSizes& s) {
    auto perSample = [&s](VkFormat format) {
        return rg::ImageDesc::absolute(format, s.samples, s.slices);
    };
    EpipolarCoordinates out;
    out.coordinates = g.createImage("coordinate texture", perSample(in.chain.coordinateFormat));
    out.epipolarZ = g.createImage("epipolar camera-space z", perSample(VK_FORMAT_R32_SFLOAT));
    auto pass = g.addPass("coordinates and epipolar z", rg::PassType::Graphics);
    const auto& sm = samplersOf(in.chain.shared);
    rg::BindingTable table = epipolarTable(pass, in.chain, in.epipolar);
    table.sampled(LS_BINDING_COORDINATES_END_POINTS, in.sliceEndPoints, sm.nearest())
        .sampled(LS_BINDING_COORDINATES_DEPTH, in.chain.depth, sm.nearest(),
                 VK_IMAGE_ASPECT_DEPTH_BIT);
    // Invalid samples keep the clear values: epipolar z -1, which no valid sample has, tells them
    // apart (the coordinates of invalid samples are never read).
    out.coordinates = pass.colorAttachment(out.coordinates, rg::LoadOp::Clear);
    out.epipolarZ =
        pass.colorAttachment(out.epipolarZ, rg::LoadOp::Clear, {{-1.0f, 0.0f, 0.0f, 0.0f}});
    pass.execute([shared = in.chain.shared, table](rg::PassContext& ctx) {
        auto desc =
            fullscreenPipeline(rg::spirv(ls_spirv::epipolar_coordinates_frag), ctx, table.layout());
        const auto& p = shared->pipelines.graphics("coordinates and epipolar z", desc);
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
    return out;
}

}  // namespace ls
