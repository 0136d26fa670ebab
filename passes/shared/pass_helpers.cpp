#include "pass_helpers.h"

#include "fullscreen_vert.h"

namespace ls {

rg::DescriptorPush frameSet(const rg::PassContext& ctx, rg::BufferRef constants) {
    rg::DescriptorPush set;
    set.uniform(0, ctx.buffer(constants));
    return set;
}

rg::Binding sampledBinding(uint32_t binding) {
    return {binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_ALL};
}
rg::Binding storageBinding(uint32_t binding) {
    return {binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_ALL};
}
rg::Binding uniformBinding(uint32_t binding) {
    return {binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_ALL};
}
rg::Binding storageBufferBinding(uint32_t binding) {
    return {binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_ALL};
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

std::string pipelineKey(const std::string& name, const rg::PassContext& ctx,
                        const std::string& variant) {
    std::string key = name + "/" + variant;
    const auto& f = ctx.renderingFormats();
    for (VkFormat c : f.colors) key += "/c" + std::to_string(static_cast<int>(c));
    key += "/d" + std::to_string(static_cast<int>(f.depth)) + "/s" +
           std::to_string(static_cast<int>(f.stencil));
    return key;
}

}  // namespace ls

namespace ls {

void declareMarchInputs(rg::PassBuilder& pass, const NodeInputs& in) {
    if (in.shadowMap.valid()) pass.sampled(in.shadowMap, 0, VK_IMAGE_ASPECT_DEPTH_BIT);
    if (in.table.valid()) pass.sampled(in.table);
    if (in.lightColor.valid()) pass.sampled(in.lightColor);
}

void appendMarchBindings(std::vector<rg::Binding>& bindings, const NodeInputs& in) {
    if (in.shadowMap.valid()) bindings.push_back(sampledBinding(6));
    if (in.table.valid()) bindings.push_back(sampledBinding(7));
    if (in.lightColor.valid()) bindings.push_back(sampledBinding(8));
}

void pushMarchInputs(rg::DescriptorPush& set, const rg::PassContext& ctx, const NodeInputs& in) {
    const auto& s = in.shared->samplers;
    if (in.shadowMap.valid())
        set.sampled(6, ctx.view(in.shadowMap, VK_IMAGE_ASPECT_DEPTH_BIT), ctx.layout(in.shadowMap),
                    s.nearest());
    if (in.table.valid()) set.sampled(7, ctx.view(in.table), ctx.layout(in.table), s.nearest());
    if (in.lightColor.valid())
        set.sampled(8, ctx.view(in.lightColor), ctx.layout(in.lightColor), s.linear());
}

}  // namespace ls
