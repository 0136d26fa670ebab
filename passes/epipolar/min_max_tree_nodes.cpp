#include "epipolar_nodes.h"
#include "epipolar_shaders.h"
#include "min_max_first_level_comp_variants.h"
#include "min_max_next_level_comp.h"
#include "min_max_trees.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"
#include "shared/shader_variant.h"

namespace ls {
namespace {

// min_max_next_level.comp's push block (its fields written once, in min_max_push_fields.h).
struct TreeLevelPush {
#define LS_INT int32_t
#include "shaders/epipolar/min_max_push_fields.h"
#undef LS_INT
};

}  // namespace

rg::ShaderCode minMaxFirstLevelShader(bool cubeShadow) {
    return pickShader(ls_spirv::min_max_first_level_comp_variants,
                      {{"LS_CUBE_SHADOW", cubeShadow}});
}

// One node per tree level: the first from the shadow map, each coarser one from the level below.
// Every level lives in one texture (the levels' columns are disjoint): each pass reads the level
// below and writes its own, and keeps what earlier passes wrote, so it read-modify-writes it.
rg::ImageRef addMinMaxTrees(rg::RenderGraph& g, const MinMaxTreesInputs& in,
                            const EpipolarSizes& s) {
    const uint32_t n = in.light.shadowMapSize;
    const uint32_t levels = treeLevels(n);
    const int face = in.epipolar.face;
    rg::ImageRef tree = g.createImage(
        "1D min/max trees", rg::ImageDesc::absolute(VK_FORMAT_R16G16_SFLOAT, n, s.slices));
    {
        auto pass = g.addPass("min/max trees level 1", rg::PassType::Compute);
        const auto& sm = samplersOf(in.chain.shared);
        rg::BindingTable table = epipolarTable(pass, in.chain, in.epipolar);
        table
            .sampled(LS_BINDING_TREE_SHADOW_MAP, in.light.shadowMap, sm.nearest(),
                     VK_IMAGE_ASPECT_DEPTH_BIT)
            .sampled(LS_BINDING_TREE_UV_FRAME, in.sliceUvFrame, sm.nearest());
        tree = table.storageWrite(LS_BINDING_TREE_FIRST_LEVEL, tree);
        pass.execute([frame = in.chain, face, table, s, n](rg::PassContext& ctx) {
            // A cube face out of view.
            if (!epipolarFrameOf(ctx.data(frame.values)).inView(face)) return;
            const Shared& shared = frame.shared;
            // A point light's cube map: the face's layer of the 2D array.
            const bool cube = frame.spec.cubeShadow;
            const auto& p = shared->pipelines.compute(
                cube ? "min/max trees level 1 (cube face)" : "min/max trees level 1",
                minMaxFirstLevelShader(cube), table.layout(), 0, {});
            p.bind(ctx.cmd());
            table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
            ctx.vk().CmdDispatch(ctx.cmd(), groupCount(n / 2, 64), s.slices, 1);
        });
    }
    for (uint32_t level = 2; level <= levels; ++level) {
        auto pass =
            g.addPass("min/max trees level " + std::to_string(level), rg::PassType::Compute);
        rg::BindingTable table(pass);
        tree = table.storageReadWrite(LS_BINDING_TREE_LEVEL, tree);
        pass.execute([frame = in.chain, face, table, level, n, s](rg::PassContext& ctx) {
            if (!epipolarFrameOf(ctx.data(frame.values)).inView(face)) return;
            const Shared& shared = frame.shared;
            const auto& p = shared->pipelines.compute("min/max trees next level",
                                                      rg::spirv(ls_spirv::min_max_next_level_comp),
                                                      table.layout(), sizeof(TreeLevelPush), {});
            p.bind(ctx.cmd());
            table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
            p.push(ctx.cmd(), TreeLevelPush{static_cast<int32_t>(level), static_cast<int32_t>(n)});
            ctx.vk().CmdDispatch(ctx.cmd(), groupCount(n >> level, 64), s.slices, 1);
        });
    }
    return tree;
}

}  // namespace ls
