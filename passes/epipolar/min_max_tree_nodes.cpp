#include "epipolar_nodes.h"
#include "epipolar_shaders.h"
#include "min_max_first_level_comp_variants.h"
#include "min_max_next_level_comp_variants.h"
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

rg::ShaderCode minMaxNextLevelShader(bool cubeShadow) {
    return pickShader(ls_spirv::min_max_next_level_comp_variants, {{"LS_CUBE_SHADOW", cubeShadow}});
}

// One node per tree level: the first from the shadow map, each coarser one from the level below.
// Every level lives in one texture (the levels' columns are disjoint): each pass reads the level
// below and writes its own, and keeps what earlier passes wrote, so it read-modify-writes it. A
// point light's cube: the six faces' trees in one dispatch per level, a layer each (those of the
// faces out of view are left unwritten, and nothing reads them).
rg::ImageRef addMinMaxTrees(rg::RenderGraph& g, const MinMaxTreesInputs& in,
                            const EpipolarSizes& s) {
    const uint32_t n = in.light.shadowMapSize;
    const uint32_t levels = treeLevels(n);
    const bool cube = in.chain.spec.cubeShadow;
    const uint32_t faces = cube ? 6 : 1;
    rg::ImageDesc desc = rg::ImageDesc::absolute(VK_FORMAT_R16G16_SFLOAT, n, s.slices);
    desc.arrayLayers = faces;
    rg::ImageRef tree = g.createImage("1D min/max trees", desc);
    {
        auto pass = g.addPass("min/max trees level 1", rg::PassType::Compute);
        const auto& sm = samplersOf(in.chain.shared);
        rg::BindingTable table = epipolarTable(pass, in.chain, in.epipolar);
        table
            .sampled(LS_BINDING_TREE_SHADOW_MAP, in.light.shadowMap, sm.nearest(),
                     VK_IMAGE_ASPECT_DEPTH_BIT)
            .sampled(LS_BINDING_TREE_UV_FRAME, in.sliceUvFrame, sm.nearest());
        tree = table.storageWrite(LS_BINDING_TREE_FIRST_LEVEL, tree);
        pass.execute([frame = in.chain, cube, faces, table, s, n](rg::PassContext& ctx) {
            const Shared& shared = frame.shared;
            const auto& p = shared->pipelines.compute(
                cube ? "min/max trees level 1 (cube faces)" : "min/max trees level 1",
                minMaxFirstLevelShader(cube), table.layout(), 0, {});
            p.bind(ctx.cmd());
            table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
            ctx.vk().CmdDispatch(ctx.cmd(), groupCount(n / 2, 64), s.slices, faces);
        });
    }
    for (uint32_t level = 2; level <= levels; ++level) {
        auto pass =
            g.addPass("min/max trees level " + std::to_string(level), rg::PassType::Compute);
        rg::BindingTable table(pass);
        tree = table.storageReadWrite(LS_BINDING_TREE_LEVEL, tree);
        pass.execute([frame = in.chain, cube, faces, table, level, n, s](rg::PassContext& ctx) {
            const Shared& shared = frame.shared;
            const auto& p = shared->pipelines.compute(
                cube ? "min/max trees next level (cube faces)" : "min/max trees next level",
                minMaxNextLevelShader(cube), table.layout(), sizeof(TreeLevelPush), {});
            p.bind(ctx.cmd());
            table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
            const auto inView =
                static_cast<int32_t>(epipolarFrameOf(ctx.data(frame.values)).constants.cubeFaces.x);
            p.push(ctx.cmd(),
                   TreeLevelPush{static_cast<int32_t>(level), static_cast<int32_t>(n), inView});
            ctx.vk().CmdDispatch(ctx.cmd(), groupCount(n >> level, 64), s.slices, faces);
        });
    }
    return tree;
}

}  // namespace ls
