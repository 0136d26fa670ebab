#include "memory_counter.h"

#include <atomic>

namespace rg {
namespace {

std::atomic<uint64_t> gBytes{0};

}  // namespace

uint64_t deviceMemoryInUse() {
    return gBytes.load();
}

namespace detail {

void countDeviceMemory(VkDeviceSize bytes) {
    gBytes += bytes;
}
void uncountDeviceMemory(VkDeviceSize bytes) {
    gBytes -= bytes;
}

}  // namespace detail
}  // namespace rg
