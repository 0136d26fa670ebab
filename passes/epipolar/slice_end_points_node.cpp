#include "epipolar_nodes.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"
#include "slice_end_points_comp.h"

namespace ls {

rg::ImageRef addSliceEndPoints(rg::RenderGraph& g, const SliceEndPointsInputs& in,
                               const EpipolarSizes& s) {
    const rg::ImageRef endPoints = g.createImage(
        "slice end points", rg::ImageDesc::absolute(VK_FORMAT_R32G32B32A32_SFLOAT, s.slices, 1));
    auto pass = g.addPass("slice end points", rg::PassType::Compute);
    rg::BindingTable table = epipolarTable(pass, in.chain, in.epipolar);
    const rg::ImageRef out = table.storageWrite(LS_BINDING_SLICE_END_POINTS_OUT, endPoints);
    pass.execute([shared = in.chain.shared, table, s](rg::PassContext& ctx) {
        const auto& p = shared->pipelines.compute(
            "slice end points", rg::spirv(ls_spirv::slice_end_points_comp), table.layout(), 0, {});
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDispatch(ctx.cmd(), groupCount(s.slices, 64), 1, 1);
    });
    return out;
}

}  // namespace ls
