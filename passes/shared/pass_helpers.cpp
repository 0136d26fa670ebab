#include "pass_helpers.h"

#include "fullscreen_vert.h"

namespace ls {

rg::BindingTable frameTable(rg::PassBuilder& pass, rg::BufferRef constants,
                            VkPipelineStageFlags2 stages) {
    rg::BindingTable table(pass);
    table.uniform(LS_BINDING_FRAME, constants, stages);
    return table;
}

rg::GraphicsPipelineDesc fullscreenPipeline(rg::ShaderCode fragment, const rg::PassContext& ctx,
                                            std::vector<rg::Binding> bindings) {
    rg::GraphicsPipelineDesc d;
    d.vertex = rg::spirv(ls_spirv::fullscreen_vert);
    d.fragment = fragment;
    d.formats = ctx.renderingFormats();
    d.bindings = std::move(bindings);
    return d;
}

}  // namespace ls

namespace ls {

void addMarchInputs(rg::BindingTable& table, const Shared& shared, const LightImages& light) {
    const auto& s = samplersOf(shared);
    table
        .sampledIfValid(LS_BINDING_SHADOW_MAP, light.shadowMap, s.nearest(),
                        VK_IMAGE_ASPECT_DEPTH_BIT)
        .sampledIfValid(LS_BINDING_POINT_TABLE, light.table, s.nearest())
        .sampledIfValid(LS_BINDING_LIGHT_COLOR, light.lightColor, s.linear());
}

bool scissorToLight(rg::PassContext& ctx, rg::HostDataRef<LightFrame> values) {
    const VkRect2D rect = ctx.data(values).screenRect;
    if (rect.extent.width == 0 || rect.extent.height == 0) return false;
    ctx.vk().CmdSetScissor(ctx.cmd(), 0, 1, &rect);
    return true;
}

}  // namespace ls
