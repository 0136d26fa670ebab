#include "binding_table.h"

namespace rg {

BindingTable& BindingTable::add(const Row& row) {
    // Two rows on one binding are left to the pipeline's layout creation, which the validation
    // layer rejects (declaring never fails: see render_graph.h).
    rows_.push_back(row);
    return *this;
}

bool BindingTable::has(uint32_t binding) const {
    for (const Row& r : rows_)
        if (r.binding == binding) return true;
    return false;
}

BindingTable& BindingTable::uniform(uint32_t binding, BufferRef buffer,
                                    VkPipelineStageFlags2 stages) {
    pass_->uniformBuffer(buffer, stages);
    return add({binding, BindingKind::Uniform, {}, buffer});
}

BindingTable& BindingTable::sampled(uint32_t binding, ImageRef image, VkSampler sampler,
                                    VkImageAspectFlags aspect, VkPipelineStageFlags2 stages) {
    pass_->sampled(image, stages, aspect);
    return add({binding, BindingKind::Sampled, image, {}, aspect, sampler});
}

BindingTable& BindingTable::storageRead(uint32_t binding, ImageRef image,
                                        VkPipelineStageFlags2 stages) {
    pass_->storageRead(image, stages);
    return add({binding, BindingKind::Storage, image, {}});
}

ImageRef BindingTable::storageWrite(uint32_t binding, ImageRef image,
                                    VkPipelineStageFlags2 stages) {
    const ImageRef written = pass_->storageWrite(image, stages);
    add({binding, BindingKind::Storage, written, {}});
    return written;
}

ImageRef BindingTable::storageReadWrite(uint32_t binding, ImageRef image,
                                        VkPipelineStageFlags2 stages) {
    const ImageRef written = pass_->storageReadWrite(image, stages);
    add({binding, BindingKind::Storage, written, {}});
    return written;
}

BindingTable& BindingTable::storageBufferRead(uint32_t binding, BufferRef buffer,
                                              VkPipelineStageFlags2 stages) {
    pass_->storageBufferRead(buffer, stages);
    return add({binding, BindingKind::StorageBuffer, {}, buffer});
}

BufferRef BindingTable::storageBufferReadWrite(uint32_t binding, BufferRef buffer,
                                               VkPipelineStageFlags2 stages) {
    const BufferRef written = pass_->storageBufferReadWrite(buffer, stages);
    add({binding, BindingKind::StorageBuffer, {}, written});
    return written;
}

BindingTable& BindingTable::sampledIfValid(uint32_t binding, ImageRef image, VkSampler sampler,
                                           VkImageAspectFlags aspect) {
    return image.valid() ? sampled(binding, image, sampler, aspect) : *this;
}

ImageRef BindingTable::storageReadWriteIfValid(uint32_t binding, ImageRef image) {
    return image.valid() ? storageReadWrite(binding, image) : ImageRef{};
}

BufferRef BindingTable::storageBufferReadWriteIfValid(uint32_t binding, BufferRef buffer) {
    return buffer.valid() ? storageBufferReadWrite(binding, buffer) : BufferRef{};
}

BindingTable BindingTable::without(uint32_t binding) const {
    BindingTable t = *this;
    std::erase_if(t.rows_, [binding](const Row& r) { return r.binding == binding; });
    return t;
}

std::vector<Binding> BindingTable::layout() const {
    std::vector<Binding> bindings;
    bindings.reserve(rows_.size());
    for (const Row& r : rows_) {
        VkDescriptorType type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        switch (r.kind) {
            case BindingKind::Uniform:
                type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
                break;
            case BindingKind::Sampled:
                type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
                break;
            case BindingKind::Storage:
                type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
                break;
            case BindingKind::StorageBuffer:
                type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                break;
        }
        bindings.push_back({r.binding, type, VK_SHADER_STAGE_ALL});
    }
    return bindings;
}

DescriptorPush BindingTable::writes(const PassContext& ctx) const {
    DescriptorPush set;
    for (const Row& r : rows_) {
        switch (r.kind) {
            case BindingKind::Uniform:
                set.uniform(r.binding, ctx.buffer(r.buffer));
                break;
            case BindingKind::Sampled:
                set.sampled(r.binding, ctx.view(r.image, r.aspect), ctx.layout(r.image), r.sampler);
                break;
            case BindingKind::Storage:
                set.storage(r.binding, ctx.view(r.image));
                break;
            case BindingKind::StorageBuffer:
                set.storageBuffer(r.binding, ctx.buffer(r.buffer));
                break;
        }
    }
    return set;
}

}  // namespace rg
