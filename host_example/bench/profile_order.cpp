#include "profile_order.h"

#include <cstdio>
#include <map>
#include <utility>

#include "metrics.h"

namespace host::bench {

ProfileOrderCheck checkProfileOrder(const nlohmann::json& runs, double tolerance) {
    static const char* const kChains[2][3] = {
        {"high-quality", "balanced", "high-performance"},
        {"low-high-quality", "low-balanced", "low-high-performance"}};
    // (scene, size) -> profile -> each round's median ms
    std::map<std::pair<std::string, std::string>, std::map<std::string, std::vector<double>>>
        rounds;
    for (const nlohmann::json& r : runs) {
        if (r.value("family", "") != "profiles" || r.value("method", "") != "epipolar") continue;
        const std::string size = std::to_string(r["size"][0].get<unsigned>()) + "x" +
                                 std::to_string(r["size"][1].get<unsigned>());
        rounds[{r["scene"].get<std::string>(), size}][r["profile"].get<std::string>()].push_back(
            r["time"]["median"].get<double>());
    }
    std::map<std::pair<std::string, std::string>, std::map<std::string, double>> medians;
    // The bench's median, as of a run's frames.
    for (const auto& [where, profiles] : rounds)
        for (const auto& [profile, times] : profiles)
            medians[where][profile] = spreadOf(times).median;
    ProfileOrderCheck check;
    for (const auto& [where, times] : medians)
        for (const auto& chain : kChains)
            for (int k = 1; k < 3; ++k) {
                const auto before = times.find(chain[k - 1]), after = times.find(chain[k]);
                if (before == times.end() || after == times.end()) continue;
                ++check.pairs;
                if (after->second <= before->second * (1.0 + tolerance)) continue;
                char line[512];
                std::snprintf(
                    line, sizeof line, "%s %s: %s takes %.1f ms, %.1f%% more than %s's %.1f ms",
                    where.first.c_str(), where.second.c_str(), chain[k], after->second,
                    100.0 * (after->second / before->second - 1.0), chain[k - 1], before->second);
                check.broken.push_back(line);
            }
    return check;
}

}  // namespace host::bench
