#include "epipolar_nodes.h"
#include "epipolar_shaders.h"
#include "min_max_trees.h"
#include "min_max_trees_comp_variants.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"
#include "shared/shader_variant.h"

namespace ls {

rg::ShaderCode minMaxTreesShader(bool cubeShadow) {
    return pickShader(ls_spirv::min_max_trees_comp_variants, {{"LS_CUBE_SHADOW", cubeShadow}});
}

// Every level of every slice's tree in one pass, a workgroup per slice (min_max_trees.comp): the
// levels share one texture (their columns are disjoint). A point light's cube: the six faces'
// trees in the same dispatch, a layer each (those of the faces out of view are left unwritten, and
// nothing reads them).
rg::ImageRef addMinMaxTrees(rg::RenderGraph& g, const MinMaxTreesInputs& in,
                            const EpipolarSizes& s) {
    const uint32_t n = in.light.shadowMapSize;
    const bool cube = in.chain.spec.cubeShadow;
    const uint32_t faces = cube ? 6 : 1;
    rg::ImageDesc desc = rg::ImageDesc::absolute(VK_FORMAT_R16G16_SFLOAT, n, s.slices);
    desc.arrayLayers = faces;
    rg::ImageRef tree = g.createImage("1D min/max trees", desc);
    auto pass = g.addPass("min/max trees", rg::PassType::Compute);
    const auto& sm = samplersOf(in.chain.shared);
    rg::BindingTable table = epipolarTable(pass, in.chain, in.epipolar);
    table
        .sampled(LS_BINDING_TREE_SHADOW_MAP, in.light.shadowMap, sm.nearest(),
                 VK_IMAGE_ASPECT_DEPTH_BIT)
        .sampled(LS_BINDING_TREE_UV_FRAME, in.sliceUvFrame, sm.nearest());
    tree = table.storageWrite(LS_BINDING_TREE_OUT, tree);
    pass.execute([frame = in.chain, cube, faces, table, s](rg::PassContext& ctx) {
        const Shared& shared = frame.shared;
        const auto& p =
            shared->pipelines.compute(cube ? "min/max trees (cube faces)" : "min/max trees",
                                      minMaxTreesShader(cube), table.layout(), 0, {});
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDispatch(ctx.cmd(), 1, s.slices, faces);
    });
    return tree;
}

}  // namespace ls
