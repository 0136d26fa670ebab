#include "shared/pass_helpers.h"
#include "epipolar_coordinates_frag.h"
#include "epipolar_nodes.h"

namespace ls {

void addEpipolarCoordinates(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                            EpipolarTextures& t) {
    t.coordinates = g.createImage("coordinate texture",
                                  rg::ImageDesc::absolute(VK_FORMAT_R32G32_SFLOAT, s.samples, s.slices));
    t.epipolarZ = g.createImage("epipolar camera-space z",
                                rg::ImageDesc::absolute(VK_FORMAT_R32_SFLOAT, s.samples, s.slices));
    t.epipolarStencil = g.createImage("epipolar depth-stencil",
                                      rg::ImageDesc::absolute(in.depthStencil, s.samples, s.slices));
    auto pass = g.addPass("coordinates and epipolar z", rg::PassType::Graphics);
    pass.uniformBuffer(in.constants);
    pass.sampled(t.sliceEndPoints);
    pass.sampled(t.cameraZ);
    // Cleared to values no valid sample has: the later passes tell valid samples by them too.
    t.coordinates = pass.colorAttachment(t.coordinates, rg::LoadOp::Clear, {{-1e4f, -1e4f, 0.0f, 0.0f}});
    t.epipolarZ = pass.colorAttachment(t.epipolarZ, rg::LoadOp::Clear, {{-1.0f, 0.0f, 0.0f, 0.0f}});
    t.epipolarStencil = pass.stencilWrite(t.epipolarStencil, rg::LoadOp::Clear, 0);
    const EpipolarTextures tex = t;
    pass.execute([in, tex](rg::PassContext& ctx) {
        auto desc = fullscreenPipeline(rg::spirv(ls_spirv::epipolar_coordinates_frag), ctx,
                                       {uniformBinding(0), sampledBinding(1), sampledBinding(2)});
        desc.stencilTest = true;
        desc.stencil = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_REPLACE, VK_STENCIL_OP_KEEP,
                        VK_COMPARE_OP_ALWAYS, 0xff, 0xff, 1};
        const auto& p = in.shared->pipelines.graphics(pipelineKey("coordinates and epipolar z", ctx), desc);
        p.bind(ctx.cmd());
        vkCmdSetStencilReference(ctx.cmd(), VK_STENCIL_FACE_FRONT_AND_BACK, 1);
        frameSet(ctx, in.constants)
            .sampled(1, ctx.view(tex.sliceEndPoints), ctx.layout(tex.sliceEndPoints),
                     in.shared->samplers.nearest())
            .sampled(2, ctx.view(tex.cameraZ), ctx.layout(tex.cameraZ), in.shared->samplers.nearest())
            .push(ctx.device(), ctx.cmd(), p);
        vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    });
}

}  // namespace ls
