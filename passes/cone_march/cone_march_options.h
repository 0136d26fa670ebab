#pragma once
// Seed 003's march, as its node takes it.
#include <cstdint>

namespace ls {

struct ConeMarchOptions {
    bool operator==(const ConeMarchOptions&) const = default;
    uint32_t samples = 32;    // per pixel
    bool coneLimited = true;  // false: march all of [0, S] (seed 003's naive baseline)
    bool jitter = false;      // a per-pixel offset of the samples instead of the midpoints
};

}  // namespace ls
