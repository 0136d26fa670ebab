#pragma once
// Display encoding for the PNGs the command line writes (the plugin itself hands back linear HDR).
#include <cstdint>
#include <vector>

namespace host {

// RGBA float (linear) -> RGBA8: exposure, an ACES fit (Narkowicz 2015), sRGB encoding.
std::vector<uint8_t> toneMap(const std::vector<float>& rgba, float exposure);

}  // namespace host
