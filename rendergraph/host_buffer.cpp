#include "host_buffer.h"

#include "device_memory.h"
#include "fault_injection.h"
#include "memory_counter.h"
#include "vk_error.h"

namespace rg {

HostBuffer::HostBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                       const std::string& name)
    : device_(device.device()), size_(size), usage_(usage) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    RG_VK_CREATE(vkCreateBuffer(device_, &info, nullptr, &buffer_));
    device.setName(buffer_, VK_OBJECT_TYPE_BUFFER, name);
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, buffer_, &req);
    const std::string what = "host-visible buffer '" + name + "'";
    try {
        const uint32_t type = device.findMemoryType(
            req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        memory_ = allocateDeviceMemory(device, req.size, type, what);
        memoryBytes_ = req.size;
        detail::countDeviceMemory(memoryBytes_);
        device.setName(memory_, VK_OBJECT_TYPE_DEVICE_MEMORY, name + " memory");
        checkBind(device, vkBindBufferMemory(device_, buffer_, memory_, 0), "vkBindBufferMemory", req.size, type,
                  what);
        RG_VK(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
    } catch (...) {
        detail::uncountDeviceMemory(memoryBytes_);
        if (memory_) vkFreeMemory(device_, memory_, nullptr);
        vkDestroyBuffer(device_, buffer_, nullptr);
        throw;
    }
}

HostBuffer::~HostBuffer() {
    detail::uncountDeviceMemory(memoryBytes_);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
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
