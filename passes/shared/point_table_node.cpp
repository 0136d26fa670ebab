#include "pass_helpers.h"
#include "shared_nodes.h"
#include "point_table_comp.h"

namespace ls {

rg::ImageRef addPointTable(rg::RenderGraph& graph, const Shared& shared, rg::BufferRef constants,
                           rg::ImageRef table) {
    auto pass = graph.addPass("point-light table", rg::PassType::Compute);
    pass.uniformBuffer(constants);
    table = pass.storageWrite(table);
    pass.execute([shared, constants, table](rg::PassContext& ctx) {
        const auto& p = shared->pipelines.compute(
            "point-light table/" + shared->spec.key(), rg::spirv(ls_spirv::point_table_comp),
            {uniformBinding(0), storageBinding(1)}, 0, shared->spec.constants());
        p.bind(ctx.cmd());
        frameSet(ctx, constants).storage(1, ctx.view(table)).push(ctx.device(), ctx.cmd(), p);
        vkCmdDispatch(ctx.cmd(), groupCount(ctx.extent(table).height, 64), 1, 1);
    });
    return table;
}

}  // namespace ls
