#include "epipolar_nodes.h"
#include "epipolar_shaders.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"
#include "shared/shader_variant.h"
#include "slice_uv_frame_comp_variants.h"

namespace ls {

// A point light's cube map: the build that takes each face's matrix from the frame's six.
rg::ShaderCode sliceUvFrameShader(bool cubeShadow) {
    return pickShader(ls_spirv::slice_uv_frame_comp_variants, {{"LS_CUBE_SHADOW", cubeShadow}});
}

rg::ImageRef addSliceUvFrame(rg::RenderGraph& g, const SliceUvFrameInputs& in,
                             const EpipolarSizes& s) {
    const uint32_t faces = in.chain.spec.cubeShadow ? 6 : 1;
    rg::ImageRef uvFrame =
        g.createImage("slice uv origin and direction",
                      rg::ImageDesc::absolute(VK_FORMAT_R32G32B32A32_SFLOAT, s.slices, faces));
    auto pass = g.addPass("slice uv origin and direction", rg::PassType::Compute);
    rg::BindingTable table = epipolarTable(pass, in.chain, in.epipolar);
    table.sampled(LS_BINDING_UV_FRAME_END_POINTS, in.sliceEndPoints,
                  samplersOf(in.chain.shared).nearest());
    uvFrame = table.storageWrite(LS_BINDING_UV_FRAME_OUT, uvFrame);
    pass.execute([frame = in.chain, table, s, faces](rg::PassContext& ctx) {
        const Shared& shared = frame.shared;
        const bool cube = frame.spec.cubeShadow;
        const auto& p = shared->pipelines.compute(
            cube ? "slice uv origin and direction (cube faces)" : "slice uv origin and direction",
            sliceUvFrameShader(cube), table.layout(), 0, {});
        p.bind(ctx.cmd());
        table.writes(ctx).push(ctx.device(), ctx.cmd(), p);
        ctx.vk().CmdDispatch(ctx.cmd(), groupCount(s.slices, 64), faces, 1);
    });
    return uvFrame;
}

}  // namespace ls
