#include "fault_injection.h"

#include <atomic>

namespace rg {
namespace {

std::atomic<uint64_t> gCount{0};
std::atomic<uint64_t> gArmedAt{0};  // absolute count that fails; 0: none

}  // namespace

void failNthVulkanCreation(uint64_t n) {
    gArmedAt = n == 0 ? 0 : gCount.load() + n;
}

uint64_t vulkanCreationCount() {
    return gCount.load();
}

namespace detail {

bool creationFails() {
    const uint64_t now = ++gCount;
    uint64_t armed = gArmedAt.load();
    return armed != 0 && now == armed && gArmedAt.compare_exchange_strong(armed, 0);
}

}  // namespace detail
}  // namespace rg
