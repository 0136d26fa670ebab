#include "tiling_noise.h"

#include "pass_helpers.h"
#include "tiling_noise_comp.h"

namespace ls {

rg::PersistentImageDesc tilingNoiseDesc() {
    rg::PersistentImageDesc d;
    d.format = kNoiseFormat;
    d.extent = kNoiseExtent;
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
    return d;
}

rg::ImageRef addTilingNoise(rg::RenderGraph& graph, const TilingNoiseInputs& in) {
    const rg::ImageRef kept = graph.persistentImage("tiling noise", tilingNoiseDesc(), in.key);
    auto pass = graph.addPass("tiling noise (seed 002)", rg::PassType::Compute);
    rg::BindingTable table(pass);
    const rg::ImageRef noise = table.storageWrite(LS_BINDING_NOISE_OUT, kept);
    pass.execute([shared = in.shared, table, noise](rg::PassContext& ctx) {
        if (ctx.persistent(noise).written) return;  // made in an earlier frame
        const auto& p = shared->pipelines.compute(
            "tiling noise", rg::spirv(ls_spirv::tiling_noise_comp), table.layout(), 0, {});
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        const VkExtent2D e = ctx.extent(noise);
        ctx.vk().CmdDispatch(ctx.cmd(), groupCount(e.width, 8), groupCount(e.height, 8), 1);
        ctx.wrote(noise, 1);
    });
    return noise;
}

}  // namespace ls
