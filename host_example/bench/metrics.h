#pragma once
// How far a method's Lin is from the float64 reference, and how long it took.
#include <cstddef>
#include <string>
#include <vector>

namespace host::bench {

struct ErrorMetrics {
    double meanRelative = 0;  // sum |a - b| / sum |b| over every pixel and channel (relative L1)
    double rmse = 0;          // root mean square of a - b, in Lin's units
    double p99 = 0;  // 99th percentile of |a - b|, divided by the reference's 99th percentile
    double max = 0;  // largest |a - b|, divided by the reference's 99th percentile
    double fractionOver = 0;  // pixels with a channel off by more than 5% of the reference's p99
    double psnr = 0;          // dB, of the tone-mapped 8-bit images (exposure, ACES, sRGB)
    size_t nonFinite = 0;     // NaN or Inf values in the method's image
};

// `method` is RGBA float (as the GPU returns it), `reference` RGB double.
ErrorMetrics compareToReference(const std::vector<float>& method,
                                const std::vector<double>& reference, float exposure);

// The p-th quantile (0..1) of `values`, nearest rank; 0 for none.
double percentile(std::vector<double> values, double p);

struct Spread {
    double median = 0, p10 = 0, p90 = 0, min = 0, max = 0;
    double mean = 0, sd = 0;  // sd: the population's (seed 003's tables give mean, SD and max)
};
Spread spreadOf(std::vector<double> values);

}  // namespace host::bench
