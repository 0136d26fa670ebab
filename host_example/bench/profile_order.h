#pragma once
// The order of epipolar's profiles in a benchmark's results: within each chain (high-quality,
// balanced, high-performance; low-high-quality, low-balanced, low-high-performance) each profile
// should cost no more than the one before it. A profile that buys less quality for more time is
// one no user should pick, and a sign that a pass's cost does not follow the profile's sizes.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace host::bench {

struct ProfileOrderCheck {
    size_t pairs = 0;                 // neighbouring profiles compared
    std::vector<std::string> broken;  // one line per pair out of order
};

// `runs` are bench.json's rows; each scene and size's epipolar profile rows (family "profiles")
// are compared by their median time (the median of those medians where rounds repeated a row:
// bench.json's "round"). A pair is out of order when the later profile's median
// exceeds the earlier's by more than `tolerance` (0.05: 5%).
ProfileOrderCheck checkProfileOrder(const nlohmann::json& runs, double tolerance);

}  // namespace host::bench
