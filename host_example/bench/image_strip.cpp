#include "image_strip.h"

#include <algorithm>
#include <cmath>

#include "image_io.h"
#include "metrics.h"
#include "tonemap.h"

namespace host::bench {

std::array<uint8_t, 4> heatColor(double t) {
    t = std::clamp(t, 0.0, 1.0);
    return {static_cast<uint8_t>(std::lround(255 * std::min(1.0, 3 * t))),
            static_cast<uint8_t>(std::lround(255 * std::clamp(3 * t - 1, 0.0, 1.0))),
            static_cast<uint8_t>(std::lround(255 * std::clamp(3 * t - 2, 0.0, 1.0))), 255};
}

void writeStrip(const std::string& path, unsigned width, unsigned height,
                const std::vector<double>& reference, const std::vector<float>& method,
                float exposure) {
    const size_t pixels = size_t{width} * height;
    std::vector<float> ref(pixels * 4, 1.0f);
    std::vector<double> values;
    for (size_t p = 0; p < pixels; ++p)
        for (size_t c = 0; c < 3; ++c) {
            ref[p * 4 + c] = static_cast<float>(reference[p * 3 + c]);
            values.push_back(reference[p * 3 + c]);
        }
    std::nth_element(values.begin(), values.begin() + static_cast<long>(values.size() * 99 / 100),
                     values.end());
    const double scale = std::max(values[values.size() * 99 / 100], 1e-30) * 0.1;
    const auto a = toneMap(ref, exposure), b = toneMap(method, exposure);
    std::vector<uint8_t> strip(pixels * 3 * 4);
    const size_t stride = size_t{width} * 3 * 4;
    for (unsigned y = 0; y < height; ++y)
        for (unsigned x = 0; x < width; ++x) {
            const size_t p = size_t{y} * width + x;
            double err = 0;
            for (size_t c = 0; c < 3; ++c) {
                const double m = method[p * 4 + c];
                err = std::max(err, std::isfinite(m) ? std::fabs(m - reference[p * 3 + c]) : 1e30);
            }
            const std::array<uint8_t, 4> heat = heatColor(err / scale);
            for (size_t c = 0; c < 4; ++c) {
                strip[y * stride + (x)*4 + c] = a[p * 4 + c];
                strip[y * stride + (width + x) * 4 + c] = b[p * 4 + c];
                strip[y * stride + (2 * width + x) * 4 + c] = heat[c];
            }
        }
    writePng(path, width * 3, height, strip);
}

void writeFlickerStrip(const std::string& path, unsigned width, unsigned height,
                       const std::vector<double>& referenceChange,
                       const std::vector<double>& excess) {
    const double scale =
        std::max({percentile(referenceChange, 0.99), percentile(excess, 0.99), 1e-30});
    std::vector<uint8_t> strip(size_t{width} * height * 2 * 4);
    for (unsigned y = 0; y < height; ++y)
        for (unsigned x = 0; x < width; ++x) {
            const size_t p = size_t{y} * width + x, row = size_t{y} * width * 2;
            const auto a = heatColor(referenceChange[p] / scale), b = heatColor(excess[p] / scale);
            std::copy(a.begin(), a.end(), strip.begin() + static_cast<long>((row + x) * 4));
            std::copy(b.begin(), b.end(), strip.begin() + static_cast<long>((row + width + x) * 4));
        }
    writePng(path, width * 2, height, strip);
}

}  // namespace host::bench
