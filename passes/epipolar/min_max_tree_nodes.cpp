#include "shared/pass_helpers.h"
#include "epipolar_nodes.h"
#include "min_max_first_level_comp.h"
#include "min_max_first_level_cube_comp.h"
#include "min_max_next_level_comp.h"

namespace ls {

// One node per tree level: the first from the shadow map, each coarser one from the level below.
// Every level lives in one texture (the levels' columns are disjoint): each pass reads the level
// below and writes its own, and keeps what earlier passes wrote, so it read-modify-writes it.
rg::ImageRef addMinMaxTrees(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                            rg::ImageRef sliceUvFrame) {
    const uint32_t n = s.shadowMapSize;
    const uint32_t levels = treeLevels(n);
    rg::ImageRef tree =
        g.createImage("1D min/max trees", rg::ImageDesc::absolute(VK_FORMAT_R16G16_SFLOAT, n, s.slices));
    {
        auto pass = g.addPass("min/max trees level 1", rg::PassType::Compute);
        pass.uniformBuffer(in.constants);
        pass.sampled(in.shadowMap, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
        pass.sampled(sliceUvFrame);
        tree = pass.storageWrite(tree);
        const rg::ImageRef level1 = tree;
        pass.execute([in, sliceUvFrame, level1, s, n](rg::PassContext& ctx) {
            if (!in.shared->inView()) return;  // a cube face out of view
            // A point light's cube map: the face's layer of the 2D array.
            const bool cube = in.shared->spec.cubeShadow;
            const auto& p = in.shared->pipelines.compute(
                cube ? "min/max trees level 1 (cube face)" : "min/max trees level 1",
                cube ? rg::spirv(ls_spirv::min_max_first_level_cube_comp)
                     : rg::spirv(ls_spirv::min_max_first_level_comp),
                {uniformBinding(0), sampledBinding(1), sampledBinding(2), storageBinding(3)}, 0, {});
            p.bind(ctx.cmd());
            frameSet(ctx, in.constants)
                .sampled(1, ctx.view(in.shadowMap, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.shadowMap),
                         in.shared->samplers.nearest())
                .sampled(2, ctx.view(sliceUvFrame), ctx.layout(sliceUvFrame),
                         in.shared->samplers.nearest())
                .storage(3, ctx.view(level1))
                .push(ctx.device(), ctx.cmd(), p);
            vkCmdDispatch(ctx.cmd(), groupCount(n / 2, 64), s.slices, 1);
        });
    }
    for (uint32_t level = 2; level <= levels; ++level) {
        auto pass = g.addPass("min/max trees level " + std::to_string(level), rg::PassType::Compute);
        tree = pass.storageReadWrite(tree);
        const rg::ImageRef written = tree;
        pass.execute([in, written, level, n, s](rg::PassContext& ctx) {
            if (!in.shared->inView()) return;
            const auto& p = in.shared->pipelines.compute(
                "min/max trees next level", rg::spirv(ls_spirv::min_max_next_level_comp), {storageBinding(0)}, 8, {});
            p.bind(ctx.cmd());
            rg::DescriptorPush().storage(0, ctx.view(written)).push(ctx.device(), ctx.cmd(), p);
            const int32_t push[2] = {static_cast<int32_t>(level), static_cast<int32_t>(n)};
            p.push(ctx.cmd(), push);
            vkCmdDispatch(ctx.cmd(), groupCount(n >> level, 64), s.slices, 1);
        });
    }
    return tree;
}

}  // namespace ls
