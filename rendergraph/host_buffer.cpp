#include "host_buffer.h"

#include "device_memory.h"
#include "memory_counter.h"
#include "vk_error.h"

namespace rg {

HostBuffer::HostBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                       const std::string& name)
    : device_(device), size_(size), usage_(usage) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    const BoundBuffer bound = createBoundBuffer(
        device, info, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
        name, "host-visible buffer '" + name + "'");
    buffer_ = bound.buffer;
    memory_ = bound.memory;
    memoryBytes_ = bound.bytes;
    detail::countDeviceMemory(memoryBytes_);
    try {
        RG_VK(device_.vk().MapMemory(device_.device(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
    } catch (...) {
        detail::uncountDeviceMemory(memoryBytes_);
        device_.vk().FreeMemory(device_.device(), memory_, device_.allocator());
        device_.vk().DestroyBuffer(device_.device(), buffer_, device_.allocator());
        throw;
    }
}

HostBuffer::~HostBuffer() {
    detail::uncountDeviceMemory(memoryBytes_);
    if (memory_) device_.vk().FreeMemory(device_.device(), memory_, device_.allocator());
    if (buffer_) device_.vk().DestroyBuffer(device_.device(), buffer_, device_.allocator());
}

ImportedBuffer HostBuffer::asReadback() const {
    ImportedBuffer b;
    b.buffer = buffer_;
    b.size = size_;
    b.usage = usage_;
    b.initialStages = VK_PIPELINE_STAGE_2_HOST_BIT;
    b.initialAccess = VK_ACCESS_2_HOST_READ_BIT;
    b.finalStages = VK_PIPELINE_STAGE_2_HOST_BIT;
    b.finalAccess = VK_ACCESS_2_HOST_READ_BIT;
    return b;
}

}  // namespace rg
