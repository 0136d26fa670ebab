#pragma once
// Pipelines for passes: compute or graphics (dynamic rendering), one push-descriptor set, push
// constants and specialisation constants. Passes own their pipelines and build them on first use,
// when the attachment formats are known.
#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "device.h"
#include "pass_context.h"

namespace rg {

struct ShaderCode {
    const uint32_t* words = nullptr;
    size_t bytes = 0;
};

template <size_t N>
ShaderCode spirv(const uint32_t (&words)[N]) {
    return {words, N * sizeof(uint32_t)};
}

struct Binding {
    uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    VkShaderStageFlags stages = VK_SHADER_STAGE_ALL;
};

// Specialisation constants as (id, 32-bit value) pairs; floats go in by bit pattern.
struct Specialization {
    std::vector<std::pair<uint32_t, uint32_t>> values;
    Specialization& set(uint32_t id, uint32_t v) {
        values.emplace_back(id, v);
        return *this;
    }
    Specialization& set(uint32_t id, int32_t v) { return set(id, static_cast<uint32_t>(v)); }
    Specialization& set(uint32_t id, bool v) { return set(id, v ? 1u : 0u); }
    Specialization& set(uint32_t id, float v);
};

// Multiply: dst.rgb * src.rgb. DualSourceMultiplyAdd: src0.rgb + dst.rgb * src1.rgb (the
// fragment's second output at index 1; needs the device's dualSrcBlend). Both keep dst.a.
enum class BlendMode : uint8_t { None, Additive, Alpha, Multiply, DualSourceMultiplyAdd };

struct GraphicsPipelineDesc {
    ShaderCode vertex;
    ShaderCode fragment;
    std::vector<Binding> bindings;
    uint32_t pushConstantBytes = 0;
    Specialization specialization;  // applied to both stages
    RenderingFormats formats;
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    std::vector<VkVertexInputBindingDescription> vertexBindings;
    std::vector<VkVertexInputAttributeDescription> vertexAttributes;
    VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
    VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    bool depthTest = false;
    bool depthWrite = false;
    VkCompareOp depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
    bool stencilTest = false;
    VkStencilOpState stencil{};  // used for front and back faces
    BlendMode blend = BlendMode::None;
    VkColorComponentFlags colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                           VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    bool depthBias = false;  // set with vkCmdSetDepthBias when enabled
};

class Pipeline {
  public:
    Pipeline() = default;
    ~Pipeline();
    Pipeline(Pipeline&& other) noexcept;
    Pipeline& operator=(Pipeline&& other) noexcept;
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    static Pipeline compute(const Device& device, const std::string& name, ShaderCode code,
                            const std::vector<Binding>& bindings, uint32_t pushConstantBytes = 0,
                            const Specialization& specialization = {});
    static Pipeline graphics(const Device& device, const std::string& name,
                             const GraphicsPipelineDesc& desc);

    explicit operator bool() const { return pipeline_ != VK_NULL_HANDLE; }
    VkPipeline handle() const { return pipeline_; }
    VkPipelineLayout layout() const { return layout_; }
    VkPipelineBindPoint bindPoint() const { return bindPoint_; }
    VkShaderStageFlags pushStages() const { return pushStages_; }

    void bind(VkCommandBuffer cmd) const {
        device_->vk().CmdBindPipeline(cmd, bindPoint_, pipeline_);
    }
    template <typename T>
    void push(VkCommandBuffer cmd, const T& constants) const {
        device_->vk().CmdPushConstants(cmd, layout_, pushStages_, 0, sizeof(T), &constants);
    }

  private:
    static Pipeline makeCompute(const Device& device, const std::string& name, ShaderCode code,
                                const std::vector<Binding>& bindings, uint32_t pushConstantBytes,
                                const Specialization& specialization);
    static Pipeline makeGraphics(const Device& device, const std::string& name,
                                 const GraphicsPipelineDesc& desc);
    void reset();
    const Device* device_ = nullptr;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineBindPoint bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
    VkShaderStageFlags pushStages_ = 0;
};

// Collects descriptor writes and pushes them with vkCmdPushDescriptorSetKHR.
class DescriptorPush {
  public:
    DescriptorPush& sampled(uint32_t binding, VkImageView view, VkImageLayout layout,
                            VkSampler sampler);
    DescriptorPush& storage(uint32_t binding, VkImageView view);  // GENERAL layout
    DescriptorPush& uniform(uint32_t binding, VkBuffer buffer, VkDeviceSize offset = 0,
                            VkDeviceSize range = VK_WHOLE_SIZE);
    DescriptorPush& storageBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset = 0,
                                  VkDeviceSize range = VK_WHOLE_SIZE);
    void push(const Device& device, VkCommandBuffer cmd, const Pipeline& pipeline);

  private:
    struct Entry {
        uint32_t binding;
        VkDescriptorType type;
        VkDescriptorImageInfo image;
        VkDescriptorBufferInfo buffer;
    };
    std::vector<Entry> entries_;
};

// The samplers the passes need: nearest and linear clamped to the edge, and linear repeating (for
// tiling textures).
class Samplers {
  public:
    explicit Samplers(const Device& device);
    // None at all (null handles): for a graph that is declared and compiled, never recorded
    // (a budget without a device).
    Samplers() = default;
    ~Samplers();
    Samplers(const Samplers&) = delete;
    Samplers& operator=(const Samplers&) = delete;
    VkSampler nearest() const { return nearest_; }
    VkSampler linear() const { return linear_; }
    VkSampler linearRepeat() const { return linearRepeat_; }

  private:
    const Device* device_ = nullptr;
    VkSampler nearest_ = VK_NULL_HANDLE;
    VkSampler linear_ = VK_NULL_HANDLE;
    VkSampler linearRepeat_ = VK_NULL_HANDLE;
};

}  // namespace rg
