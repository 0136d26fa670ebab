#pragma once
// Seed 003's cone-limited march's own settings, Settings::coneMarch (ranges and docs: its field
// table, lightscatter::settingsFields(), names "coneMarch.*"). Taken from `custom` with every
// profile.
#include <cstdint>

namespace lightscatter {

struct ConeMarchSettings {
    uint32_t samples = 32;  // samples per pixel
    bool limited = true;    // only the ray's part in the cone and range; false: the seed's naive
                            // baseline over the whole ray
    bool jitter = false;    // per-pixel jittered sample offsets instead of midpoints
};

}  // namespace lightscatter
