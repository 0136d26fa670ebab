#include "pass_helpers.h"
#include "point_table.h"
#include "point_table_comp.h"
#include "shared_nodes.h"

namespace ls {

rg::ImageRef addPointTable(rg::RenderGraph& graph, const PointTableInputs& in) {
    const rg::ImageRef kept = graph.persistentImage("point-light table", pointTableDesc(), in.key);
    auto pass = graph.addPass("point-light table", rg::PassType::Compute);
    rg::BindingTable rows = frameTable(pass, in.constants);
    const rg::ImageRef table = rows.storageWrite(LS_BINDING_POINT_TABLE_OUT, kept);
    pass.execute([shared = in.shared, spec = in.spec, values = in.values, rows,
                  table](rg::PassContext& ctx) {
        const uint64_t stamp =
            pointTableStamp(ctx.data(values).constants, spec.phase, spec.media != 0);
        const rg::PersistentState left = ctx.persistent(table);
        if (left.written && left.stamp == stamp) return;  // filled by an earlier frame
        const auto& p =
            shared->pipelines.compute("point-light table", rg::spirv(ls_spirv::point_table_comp),
                                      rows.layout(), 0, spec.constants());
        p.bind(ctx.cmd());
        rows.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDispatch(ctx.cmd(), groupCount(ctx.extent(table).height, 64), 1, 1);
        ctx.wrote(table, stamp);
    });
    return table;
}

}  // namespace ls
