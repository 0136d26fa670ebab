#pragma once
// A strip of three images for a benchmark run: the reference, the method, and a heat map of their
// difference (black 0, through red and yellow to white at 10% of the reference's 99th percentile).
#include <string>
#include <vector>

namespace host::bench {

void writeStrip(const std::string& path, unsigned width, unsigned height, const std::vector<double>& reference,
                const std::vector<float>& method, float exposure);

}  // namespace host::bench
