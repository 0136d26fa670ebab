#include "transient_heap.h"

#include <algorithm>

#include "device_memory.h"
#include "memory_counter.h"

namespace rg {

TransientHeap::TransientHeap(const Device& device, std::string name)
    : device_(device), name_(std::move(name)) {}

TransientHeap::~TransientHeap() {
    for (const Block& b : blocks_) {
        detail::uncountDeviceMemory(b.size);
        device_.vk().FreeMemory(device_.device(), b.memory, device_.allocator());
    }
}

const TransientHeap::Block* TransientHeap::find(uint32_t memoryType) const {
    for (const Block& b : blocks_)
        if (b.memoryType == memoryType) return &b;
    return nullptr;
}

void TransientHeap::reserve(const std::vector<MemoryBlockPlan>& plans, RetireList& retired,
                            uint64_t lastUse, const std::string& what) {
    // Every new allocation first, so that a failure leaves the heap as it was.
    std::vector<Block> grown;
    try {
        for (const MemoryBlockPlan& p : plans) {
            const VkDeviceSize size = std::max<VkDeviceSize>(p.size, 1);
            const Block* have = find(p.memoryType);
            if (have && have->size >= size) continue;
            Block b{p.memoryType, allocateDeviceMemory(device_, size, p.memoryType, what), size};
            detail::countDeviceMemory(size);
            grown.push_back(b);
            device_.setName(b.memory, VK_OBJECT_TYPE_DEVICE_MEMORY,
                            name_ + " (memory type " + std::to_string(p.memoryType) + ")");
        }
    } catch (...) {
        for (const Block& b : grown) {
            detail::uncountDeviceMemory(b.size);
            device_.vk().FreeMemory(device_.device(), b.memory, device_.allocator());
        }
        throw;
    }
    bool replaced = false;
    for (const Block& b : grown) {
        auto old = std::find_if(blocks_.begin(), blocks_.end(),
                                [&](const Block& o) { return o.memoryType == b.memoryType; });
        if (old == blocks_.end()) {
            blocks_.push_back(b);
            continue;
        }
        retired.retire(lastUse, [&device = device_, old = *old] {
            detail::uncountDeviceMemory(old.size);
            device.vk().FreeMemory(device.device(), old.memory, device.allocator());
        });
        *old = b;
        replaced = true;
    }
    if (replaced) ++generation_;
}

bool TransientHeap::fits(const std::vector<MemoryBlockPlan>& blocks) const {
    return std::all_of(blocks.begin(), blocks.end(), [&](const MemoryBlockPlan& p) {
        return size(p.memoryType) >= std::max<VkDeviceSize>(p.size, 1);
    });
}

VkDeviceMemory TransientHeap::memory(uint32_t memoryType) const {
    const Block* b = find(memoryType);
    return b ? b->memory : VK_NULL_HANDLE;
}

VkDeviceSize TransientHeap::size(uint32_t memoryType) const {
    const Block* b = find(memoryType);
    return b ? b->size : 0;
}

VkDeviceSize TransientHeap::bytes() const {
    VkDeviceSize total = 0;
    for (const Block& b : blocks_) total += b.size;
    return total;
}

}  // namespace rg
