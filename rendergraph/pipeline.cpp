#include "pipeline.h"

#include <cstring>
#include <utility>

#include "fault_injection.h"
#include "vk_error.h"

namespace rg {
namespace {

VkShaderModule makeModule(const Device& device, ShaderCode code) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = code.bytes;
    info.pCode = code.words;
    VkShaderModule m;
    RG_VK_CREATE(device.vk().CreateShaderModule(device.device(), &info, device.allocator(), &m));
    return m;
}

struct SpecData {
    std::vector<VkSpecializationMapEntry> entries;
    std::vector<uint32_t> data;
    VkSpecializationInfo info{};
    explicit SpecData(const Specialization& s) {
        for (const auto& [id, v] : s.values) {
            entries.push_back(
                {id, static_cast<uint32_t>(data.size() * sizeof(uint32_t)), sizeof(uint32_t)});
            data.push_back(v);
        }
        info.mapEntryCount = static_cast<uint32_t>(entries.size());
        info.pMapEntries = entries.data();
        info.dataSize = data.size() * sizeof(uint32_t);
        info.pData = data.data();
    }
    const VkSpecializationInfo* get() const { return entries.empty() ? nullptr : &info; }
};

void makeLayout(const Device& device, const std::string& name, const std::vector<Binding>& bindings,
                uint32_t pushBytes, VkShaderStageFlags pushStages, VkDescriptorSetLayout& setLayout,
                VkPipelineLayout& layout) {
    std::vector<VkDescriptorSetLayoutBinding> b;
    for (const auto& x : bindings) b.push_back({x.binding, x.type, 1, x.stages, nullptr});
    VkDescriptorSetLayoutCreateInfo set{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    set.bindingCount = static_cast<uint32_t>(b.size());
    set.pBindings = b.data();
    RG_VK_CREATE(device.vk().CreateDescriptorSetLayout(device.device(), &set, device.allocator(),
                                                       &setLayout));
    device.setName(setLayout, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, name + " set layout");
    VkPushConstantRange range{pushStages, 0, pushBytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = 1;
    info.pSetLayouts = &setLayout;
    info.pushConstantRangeCount = pushBytes ? 1 : 0;
    info.pPushConstantRanges = &range;
    RG_VK_CREATE(
        device.vk().CreatePipelineLayout(device.device(), &info, device.allocator(), &layout));
    device.setName(layout, VK_OBJECT_TYPE_PIPELINE_LAYOUT, name + " layout");
}

}  // namespace

Specialization& Specialization::set(uint32_t id, float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return set(id, bits);
}

Pipeline::~Pipeline() {
    reset();
}

Pipeline::Pipeline(Pipeline&& o) noexcept {
    *this = std::move(o);
}

Pipeline& Pipeline::operator=(Pipeline&& o) noexcept {
    if (this != &o) {
        reset();
        device_ = std::exchange(o.device_, nullptr);
        pipeline_ = std::exchange(o.pipeline_, VK_NULL_HANDLE);
        layout_ = std::exchange(o.layout_, VK_NULL_HANDLE);
        setLayout_ = std::exchange(o.setLayout_, VK_NULL_HANDLE);
        bindPoint_ = o.bindPoint_;
        pushStages_ = o.pushStages_;
    }
    return *this;
}

void Pipeline::reset() {
    if (!device_) return;
    if (pipeline_)
        device_->vk().DestroyPipeline(device_->device(), pipeline_, device_->allocator());
    if (layout_)
        device_->vk().DestroyPipelineLayout(device_->device(), layout_, device_->allocator());
    if (setLayout_)
        device_->vk().DestroyDescriptorSetLayout(device_->device(), setLayout_,
                                                 device_->allocator());
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    setLayout_ = VK_NULL_HANDLE;
    device_ = nullptr;
}

Pipeline Pipeline::compute(const Device& device, const std::string& name, ShaderCode code,
                           const std::vector<Binding>& bindings, uint32_t pushConstantBytes,
                           const Specialization& specialization) {
    try {
        return makeCompute(device, name, code, bindings, pushConstantBytes, specialization);
    } catch (const VulkanError& e) {
        throw VulkanError("pipeline '" + name + "': " + e.what());
    }
}

Pipeline Pipeline::graphics(const Device& device, const std::string& name,
                            const GraphicsPipelineDesc& d) {
    try {
        return makeGraphics(device, name, d);
    } catch (const VulkanError& e) {
        throw VulkanError("pipeline '" + name + "': " + e.what());
    }
}

Pipeline Pipeline::makeCompute(const Device& device, const std::string& name, ShaderCode code,
                               const std::vector<Binding>& bindings, uint32_t pushConstantBytes,
                               const Specialization& specialization) {
    Pipeline p;
    p.device_ = &device;
    p.bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
    p.pushStages_ = VK_SHADER_STAGE_COMPUTE_BIT;
    makeLayout(device, name, bindings, pushConstantBytes, p.pushStages_, p.setLayout_, p.layout_);
    VkShaderModule module = makeModule(device, code);
    SpecData spec(specialization);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = spec.get();
    info.layout = p.layout_;
    const VkResult r = detail::creationFails() ? VK_ERROR_OUT_OF_DEVICE_MEMORY
                                               : device.vk().CreateComputePipelines(
                                                     device.device(), VK_NULL_HANDLE, 1, &info,
                                                     device.allocator(), &p.pipeline_);
    device.vk().DestroyShaderModule(device.device(), module, device.allocator());
    check(r, "vkCreateComputePipelines");
    device.setName(p.pipeline_, VK_OBJECT_TYPE_PIPELINE, name);
    return p;
}

Pipeline Pipeline::makeGraphics(const Device& device, const std::string& name,
                                const GraphicsPipelineDesc& d) {
    Pipeline p;
    p.device_ = &device;
    p.bindPoint_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
    p.pushStages_ = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    makeLayout(device, name, d.bindings, d.pushConstantBytes, p.pushStages_, p.setLayout_,
               p.layout_);
    VkShaderModule vs = makeModule(device, d.vertex);
    VkShaderModule fs = VK_NULL_HANDLE;
    try {
        fs = makeModule(device, d.fragment);
    } catch (...) {
        device.vk().DestroyShaderModule(device.device(), vs, device.allocator());
        throw;
    }
    SpecData spec(d.specialization);
    VkPipelineShaderStageCreateInfo stages[2] = {
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vs;
    stages[0].pName = "main";
    stages[0].pSpecializationInfo = spec.get();
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = fs;
    stages[1].pName = "main";
    stages[1].pSpecializationInfo = spec.get();

    VkPipelineVertexInputStateCreateInfo vertexInput{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertexInput.vertexBindingDescriptionCount = static_cast<uint32_t>(d.vertexBindings.size());
    vertexInput.pVertexBindingDescriptions = d.vertexBindings.data();
    vertexInput.vertexAttributeDescriptionCount = static_cast<uint32_t>(d.vertexAttributes.size());
    vertexInput.pVertexAttributeDescriptions = d.vertexAttributes.data();
    VkPipelineInputAssemblyStateCreateInfo assembly{
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = d.topology;
    VkPipelineViewportStateCreateInfo viewport{
        VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = d.cullMode;
    raster.frontFace = d.frontFace;
    raster.depthBiasEnable = d.depthBias;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depth{
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = d.depthTest;
    depth.depthWriteEnable = d.depthWrite;
    depth.depthCompareOp = d.depthCompare;
    depth.stencilTestEnable = d.stencilTest;
    depth.front = d.stencil;
    depth.back = d.stencil;
    std::vector<VkPipelineColorBlendAttachmentState> blends(d.formats.colors.size());
    for (auto& b : blends) {
        b = {};
        b.colorWriteMask = d.colorWriteMask;
        if (d.blend == BlendMode::Additive) {
            b.blendEnable = VK_TRUE;
            b.srcColorBlendFactor = b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
            b.srcAlphaBlendFactor = b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
        } else if (d.blend == BlendMode::Alpha) {
            b.blendEnable = VK_TRUE;
            b.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
            b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
            b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
            b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
        } else if (d.blend == BlendMode::Multiply || d.blend == BlendMode::DualSourceMultiplyAdd) {
            const bool dual = d.blend == BlendMode::DualSourceMultiplyAdd;
            b.blendEnable = VK_TRUE;
            b.srcColorBlendFactor = dual ? VK_BLEND_FACTOR_ONE : VK_BLEND_FACTOR_ZERO;
            b.dstColorBlendFactor = dual ? VK_BLEND_FACTOR_SRC1_COLOR : VK_BLEND_FACTOR_SRC_COLOR;
            b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
            b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
        }
    }
    VkPipelineColorBlendStateCreateInfo blend{
        VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = static_cast<uint32_t>(blends.size());
    blend.pAttachments = blends.data();
    std::vector<VkDynamicState> dynamic{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    if (d.stencilTest) dynamic.push_back(VK_DYNAMIC_STATE_STENCIL_REFERENCE);
    if (d.depthBias) dynamic.push_back(VK_DYNAMIC_STATE_DEPTH_BIAS);
    VkPipelineDynamicStateCreateInfo dyn{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dyn.dynamicStateCount = static_cast<uint32_t>(dynamic.size());
    dyn.pDynamicStates = dynamic.data();
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = static_cast<uint32_t>(d.formats.colors.size());
    rendering.pColorAttachmentFormats = d.formats.colors.data();
    rendering.depthAttachmentFormat = d.formats.depth;
    rendering.stencilAttachmentFormat = d.formats.stencil;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = &rendering;
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dyn;
    info.layout = p.layout_;
    const VkResult r = detail::creationFails() ? VK_ERROR_OUT_OF_DEVICE_MEMORY
                                               : device.vk().CreateGraphicsPipelines(
                                                     device.device(), VK_NULL_HANDLE, 1, &info,
                                                     device.allocator(), &p.pipeline_);
    device.vk().DestroyShaderModule(device.device(), vs, device.allocator());
    device.vk().DestroyShaderModule(device.device(), fs, device.allocator());
    check(r, "vkCreateGraphicsPipelines");
    device.setName(p.pipeline_, VK_OBJECT_TYPE_PIPELINE, name);
    return p;
}

DescriptorPush& DescriptorPush::sampled(uint32_t binding, VkImageView view, VkImageLayout layout,
                                        VkSampler sampler) {
    entries_.push_back(
        {binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {sampler, view, layout}, {}});
    return *this;
}

DescriptorPush& DescriptorPush::storage(uint32_t binding, VkImageView view) {
    entries_.push_back({binding,
                        VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                        {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL},
                        {}});
    return *this;
}

DescriptorPush& DescriptorPush::uniform(uint32_t binding, VkBuffer buffer, VkDeviceSize offset,
                                        VkDeviceSize range) {
    entries_.push_back({binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, {}, {buffer, offset, range}});
    return *this;
}

DescriptorPush& DescriptorPush::storageBuffer(uint32_t binding, VkBuffer buffer,
                                              VkDeviceSize offset, VkDeviceSize range) {
    entries_.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, {}, {buffer, offset, range}});
    return *this;
}

void DescriptorPush::push(const Device& device, VkCommandBuffer cmd, const Pipeline& pipeline) {
    std::vector<VkWriteDescriptorSet> writes;
    writes.reserve(entries_.size());
    for (const Entry& e : entries_) {
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstBinding = e.binding;
        w.descriptorCount = 1;
        w.descriptorType = e.type;
        if (e.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER ||
            e.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER)
            w.pBufferInfo = &e.buffer;
        else
            w.pImageInfo = &e.image;
        writes.push_back(w);
    }
    device.vk().CmdPushDescriptorSetKHR(cmd, pipeline.bindPoint(), pipeline.layout(), 0,
                                        static_cast<uint32_t>(writes.size()), writes.data());
    entries_.clear();
}

Samplers::Samplers(const Device& device) : device_(&device) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.addressModeU = info.addressModeV = info.addressModeW =
        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = VK_LOD_CLAMP_NONE;
    info.magFilter = info.minFilter = VK_FILTER_NEAREST;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    RG_VK_CREATE(
        device_->vk().CreateSampler(device_->device(), &info, device_->allocator(), &nearest_));
    device.setName(nearest_, VK_OBJECT_TYPE_SAMPLER, "nearest clamp sampler");
    info.magFilter = info.minFilter = VK_FILTER_LINEAR;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    try {
        RG_VK_CREATE(
            device_->vk().CreateSampler(device_->device(), &info, device_->allocator(), &linear_));
    } catch (...) {
        device_->vk().DestroySampler(device_->device(), nearest_, device_->allocator());
        throw;
    }
    device.setName(linear_, VK_OBJECT_TYPE_SAMPLER, "linear clamp sampler");
    info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    try {
        RG_VK_CREATE(device_->vk().CreateSampler(device_->device(), &info, device_->allocator(),
                                                 &linearRepeat_));
    } catch (...) {
        device_->vk().DestroySampler(device_->device(), nearest_, device_->allocator());
        device_->vk().DestroySampler(device_->device(), linear_, device_->allocator());
        throw;
    }
    device.setName(linearRepeat_, VK_OBJECT_TYPE_SAMPLER, "linear repeat sampler");
}

Samplers::~Samplers() {
    if (!device_) return;
    device_->vk().DestroySampler(device_->device(), nearest_, device_->allocator());
    device_->vk().DestroySampler(device_->device(), linear_, device_->allocator());
    device_->vk().DestroySampler(device_->device(), linearRepeat_, device_->allocator());
}

}  // namespace rg
