#pragma once
// The memory the transients of several compiled graphs are placed in, when those graphs never run
// in the same frame (an owner keeps a few and records one per frame): one block per memory type,
// as large as the largest graph's block of that type, so keeping graphs costs the largest one's
// memory rather than the sum. A graph whose first use of a block follows another graph's frame
// waits on that graph's uses (GraphExecutor::record's `before`), as an aliased first use does.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "compiled_graph.h"
#include "device.h"
#include "retire_list.h"

namespace rg {

class TransientHeap {
  public:
    TransientHeap(const Device& device, std::string name);
    // Frees the memory: every frame that used it must have completed.
    ~TransientHeap();
    TransientHeap(const TransientHeap&) = delete;
    TransientHeap& operator=(const TransientHeap&) = delete;

    // Makes room for a compiled graph's blocks. A block larger than the heap's of its memory type
    // gets new memory of its size (throws OutOfDeviceMemory naming `what`, changing nothing); the
    // memory it replaces goes to `retired`, freed after frame `lastUse`, and generation() changes
    // (a memory type met for the first time changes nothing placed before):
    // executors placed in the old memory must be made again before they record.
    void reserve(const std::vector<MemoryBlockPlan>& blocks, RetireList& retired, uint64_t lastUse,
                 const std::string& what);
    // Whether every block fits the memory the heap has (reserve() would change nothing).
    bool fits(const std::vector<MemoryBlockPlan>& blocks) const;
    // The memory of a type reserve() made room in, and its size.
    VkDeviceMemory memory(uint32_t memoryType) const;
    VkDeviceSize size(uint32_t memoryType) const;
    uint64_t generation() const { return generation_; }
    VkDeviceSize bytes() const;  // all of it

  private:
    struct Block {
        uint32_t memoryType = 0;
        VkDeviceMemory memory = VK_NULL_HANDLE;
        VkDeviceSize size = 0;
    };
    const Block* find(uint32_t memoryType) const;

    const Device& device_;
    std::string name_;
    std::vector<Block> blocks_;
    uint64_t generation_ = 0;
};

}  // namespace rg
