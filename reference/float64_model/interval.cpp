#include "interval.h"

#include <algorithm>
#include <cmath>

namespace ls::ref {

std::vector<Interval> normalizeIntervals(std::span<const Interval> intervals, double length) {
    std::vector<Interval> out;
    if (!(length > 0.0)) return out;  // also rejects NaN
    for (const Interval& in : intervals) {
        const double lo = std::max(in.begin, 0.0);
        const double hi = std::min(in.end, length);
        if (lo < hi) out.push_back({lo, hi});  // false for NaN bounds
    }
    std::sort(out.begin(), out.end(),
              [](const Interval& x, const Interval& y) { return x.begin < y.begin; });
    std::vector<Interval> merged;
    for (const Interval& in : out) {
        if (!merged.empty() && in.begin <= merged.back().end) {
            merged.back().end = std::max(merged.back().end, in.end);
        } else {
            merged.push_back(in);
        }
    }
    return merged;
}

std::vector<Interval> intersectIntervals(std::span<const Interval> a, std::span<const Interval> b) {
    std::vector<Interval> out;
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < a.size() && j < b.size()) {
        const double lo = std::max(a[i].begin, b[j].begin);
        const double hi = std::min(a[i].end, b[j].end);
        if (lo < hi) out.push_back({lo, hi});
        // The one that ends first cannot meet anything further along the other list.
        if (a[i].end < b[j].end) {
            ++i;
        } else {
            ++j;
        }
    }
    return out;
}

}  // namespace ls::ref
