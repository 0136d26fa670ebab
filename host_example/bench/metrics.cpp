#include "metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "tonemap.h"

namespace host::bench {

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0;
    const size_t k =
        std::min(v.size() - 1, static_cast<size_t>(p * static_cast<double>(v.size() - 1) + 0.5));
    std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
    return v[k];
}

ErrorMetrics compareToReference(const std::vector<float>& method,
                                const std::vector<double>& reference, float exposure) {
    ErrorMetrics m;
    const size_t pixels = reference.size() / 3;
    std::vector<double> errors, values;
    errors.reserve(reference.size());
    values.reserve(reference.size());
    double sumErr = 0, sumRef = 0, sumSq = 0;
    for (size_t p = 0; p < pixels; ++p)
        for (size_t c = 0; c < 3; ++c) {
            const double a = method[p * 4 + c], b = reference[p * 3 + c];
            if (!std::isfinite(a)) {
                ++m.nonFinite;
                continue;
            }
            const double e = std::fabs(a - b);
            errors.push_back(e);
            values.push_back(std::fabs(b));
            sumErr += e;
            sumRef += std::fabs(b);
            sumSq += e * e;
        }
    const double scale = std::max(percentile(values, 0.99), 1e-30);
    m.meanRelative = sumRef > 0 ? sumErr / sumRef : 0;
    m.rmse = errors.empty() ? 0 : std::sqrt(sumSq / static_cast<double>(errors.size()));
    m.p99 = percentile(errors, 0.99) / scale;
    m.max = errors.empty() ? 0 : *std::max_element(errors.begin(), errors.end()) / scale;
    size_t over = 0;
    for (size_t p = 0; p < pixels; ++p) {
        bool off = false;
        for (size_t c = 0; c < 3; ++c) {
            const double a = method[p * 4 + c], b = reference[p * 3 + c];
            off |= !(std::fabs(a - b) <= 0.05 * scale);
        }
        over += off ? 1 : 0;
    }
    m.fractionOver = pixels ? static_cast<double>(over) / static_cast<double>(pixels) : 0;

    std::vector<float> refRgba(pixels * 4, 1.0f);
    for (size_t p = 0; p < pixels; ++p)
        for (size_t c = 0; c < 3; ++c)
            refRgba[p * 4 + c] = static_cast<float>(reference[p * 3 + c]);
    const auto a8 = toneMap(method, exposure), b8 = toneMap(refRgba, exposure);
    double mse = 0;
    for (size_t p = 0; p < pixels; ++p)
        for (size_t c = 0; c < 3; ++c) {
            const double d =
                static_cast<double>(a8[p * 4 + c]) - static_cast<double>(b8[p * 4 + c]);
            mse += d * d;
        }
    mse /= static_cast<double>(std::max<size_t>(pixels * 3, 1));
    m.psnr = mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : 99.0;
    return m;
}

Spread spreadOf(std::vector<double> v) {
    Spread s;
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    auto at = [&](double p) {
        return v[static_cast<size_t>(p * static_cast<double>(v.size() - 1) + 0.5)];
    };
    s.median = at(0.5);
    s.p10 = at(0.1);
    s.p90 = at(0.9);
    s.min = v.front();
    s.max = v.back();
    double sum = 0.0;
    for (double x : v) sum += x;
    s.mean = sum / static_cast<double>(v.size());
    double squares = 0.0;
    for (double x : v) squares += (x - s.mean) * (x - s.mean);
    s.sd = std::sqrt(squares / static_cast<double>(v.size()));
    return s;
}

}  // namespace host::bench
