#pragma once
// The image-regression check: Lin of a render against a stored reference, tight enough that a
// broken pass shows (a block of wrong pixels, a missing light, a changed scale) while float
// differences between runs and drivers pass.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace cli_test {

struct Comparison {
    double meanError = 0;    // mean |a - b| / p99(b), over RGB
    double badFraction = 0;  // pixels with any channel off by more than 2% of p99(b)
    bool sameSize = false;
    bool pass() const { return sameSize && meanError < 2e-3 && badFraction < 5e-3; }
    std::string describe() const {
        return "mean error " + std::to_string(meanError) + " of the 99th percentile, " +
               std::to_string(badFraction * 100) +
               "% of pixels off by more than 2% (limits 0.002, 0.5%)";
    }
};

inline Comparison compareImages(const std::vector<float>& a, const std::vector<float>& b) {
    Comparison c;
    c.sameSize = a.size() == b.size() && !a.empty();
    if (!c.sameSize) return c;
    // The scale is the 99th percentile, not the maximum: a light's own glow is a few pixels far
    // brighter than the shafts the check is about.
    std::vector<float> values;
    for (size_t i = 0; i < b.size(); ++i)
        if (i % 4 != 3) values.push_back(b[i]);
    std::nth_element(values.begin(), values.begin() + static_cast<long>(values.size() * 99 / 100),
                     values.end());
    double peak = values[values.size() * 99 / 100];
    if (!(peak > 0)) peak = 1;
    double sum = 0;
    size_t bad = 0;
    for (size_t p = 0; p < b.size() / 4; ++p) {
        bool off = false;
        for (size_t k = 0; k < 3; ++k) {
            const double d = std::fabs(static_cast<double>(a[p * 4 + k]) - b[p * 4 + k]) / peak;
            sum += std::isfinite(d) ? d : 1.0;
            off |= !(d <= 0.02);
        }
        bad += off ? 1 : 0;
    }
    c.meanError = sum / static_cast<double>(b.size() / 4 * 3);
    c.badFraction = static_cast<double>(bad) / static_cast<double>(b.size() / 4);
    return c;
}

}  // namespace cli_test
