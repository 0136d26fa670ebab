#pragma once
// A strip of three images for a benchmark run: the reference, the method, and a heat map of their
// difference (black 0, through red and yellow to white at 10% of the reference's 99th percentile).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace host::bench {

// The heat map's colour for t in [0, 1]: black, red, yellow, white.
std::array<uint8_t, 4> heatColor(double t);

void writeStrip(const std::string& path, unsigned width, unsigned height,
                const std::vector<double>& reference, const std::vector<float>& method,
                float exposure);

}  // namespace host::bench

namespace host::bench {

// Where a motion run flickers: two heat maps on one scale (white at the larger of the two maps'
// 99th percentiles), the reference's own mean change per pixel and the method's mean excess over
// it (FlickerMeter's maps).
void writeFlickerStrip(const std::string& path, unsigned width, unsigned height,
                       const std::vector<double>& referenceChange,
                       const std::vector<double>& excess);

}  // namespace host::bench
