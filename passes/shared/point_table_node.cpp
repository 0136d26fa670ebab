#include "pass_helpers.h"
#include "point_table_comp.h"
#include "shared_nodes.h"

namespace ls {

rg::ImageRef addPointTable(rg::RenderGraph& graph, const PointTableInputs& in) {
    auto pass = graph.addPass("point-light table", rg::PassType::Compute);
    rg::BindingTable rows = frameTable(pass, in.constants);
    const rg::ImageRef table = rows.storageWrite(LS_BINDING_POINT_TABLE_OUT, in.table);
    pass.execute([shared = in.shared, spec = in.spec, values = in.values, rows,
                  table](rg::PassContext& ctx) {
        if (!ctx.data(values).fillTable) return;  // filled in an earlier frame
        const auto& p =
            shared->pipelines.compute("point-light table", rg::spirv(ls_spirv::point_table_comp),
                                      rows.layout(), 0, spec.constants());
        p.bind(ctx.cmd());
        rows.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDispatch(ctx.cmd(), groupCount(ctx.extent(table).height, 64), 1, 1);
    });
    return table;
}

}  // namespace ls
