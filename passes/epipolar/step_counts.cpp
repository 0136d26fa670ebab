#include "step_counts.h"

namespace ls {

std::array<uint64_t, kStepCounters> sumStepCounts(const uint32_t* rows, uint32_t slices) {
    std::array<uint64_t, kStepCounters> sum{};
    for (uint32_t s = 0; s < slices; ++s)
        for (uint32_t k = 0; k < kStepCounters; ++k) sum[k] += rows[s * kStepCountStride + k];
    return sum;
}

}  // namespace ls
