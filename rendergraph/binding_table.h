#pragma once
// A pass's binding table: one row per resource its shader binds (handle, binding, kind, and for
// sampled images the aspect and sampler). Each row declares the pass's use of the resource when it
// is added, and the same rows give the pipeline's descriptor-set layout (layout()) and the
// descriptor writes at record time (writes()), so a resource's binding is written once.
//
// Rows are added while the pass is declared (the table keeps the PassBuilder only for that); the
// table is then copied into the pass's execute callback, which calls layout() and writes().
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "pass_context.h"
#include "pipeline.h"
#include "render_graph.h"

namespace rg {

enum class BindingKind : uint8_t { Uniform, Sampled, Storage, StorageBuffer };

class BindingTable {
  public:
    explicit BindingTable(PassBuilder& pass) : pass_(&pass) {}

    BindingTable& uniform(uint32_t binding, BufferRef buffer, VkPipelineStageFlags2 stages = 0);
    BindingTable& sampled(uint32_t binding, ImageRef image, VkSampler sampler,
                          VkImageAspectFlags aspect = 0, VkPipelineStageFlags2 stages = 0);
    BindingTable& storageRead(uint32_t binding, ImageRef image, VkPipelineStageFlags2 stages = 0);
    // Writes return the image's or buffer's new version, as PassBuilder's do.
    [[nodiscard]] ImageRef storageWrite(uint32_t binding, ImageRef image,
                                        VkPipelineStageFlags2 stages = 0);
    [[nodiscard]] ImageRef storageReadWrite(uint32_t binding, ImageRef image,
                                            VkPipelineStageFlags2 stages = 0);
    BindingTable& storageBufferRead(uint32_t binding, BufferRef buffer,
                                    VkPipelineStageFlags2 stages = 0);
    [[nodiscard]] BufferRef storageBufferReadWrite(uint32_t binding, BufferRef buffer,
                                                   VkPipelineStageFlags2 stages = 0);

    // Rows for resources only some frames have: an invalid handle adds no row (no use, no layout
    // binding, no write), and a write returns the invalid handle.
    BindingTable& sampledIfValid(uint32_t binding, ImageRef image, VkSampler sampler,
                                 VkImageAspectFlags aspect = 0);
    [[nodiscard]] ImageRef storageReadWriteIfValid(uint32_t binding, ImageRef image);
    [[nodiscard]] BufferRef storageBufferReadWriteIfValid(uint32_t binding, BufferRef buffer);

    // The descriptor-set layout, every binding visible to all stages.
    std::vector<Binding> layout() const;
    // The descriptor writes, resolved against the pass being recorded.
    DescriptorPush writes(const PassContext& ctx) const;
    bool has(uint32_t binding) const;
    // The table less one row, for a draw whose shader variant lacks a binding the pass declares.
    BindingTable without(uint32_t binding) const;

  private:
    struct Row {
        uint32_t binding;
        BindingKind kind;
        ImageRef image;
        BufferRef buffer;
        VkImageAspectFlags aspect = 0;
        VkSampler sampler = VK_NULL_HANDLE;
    };
    BindingTable& add(const Row& row);

    PassBuilder* pass_;
    std::vector<Row> rows_;
};

}  // namespace rg
