#pragma once
// Temporal stability of a method under motion: how much more its Lin changes from one frame to
// the next than the float64 reference's own Lin does (the reference's change is the motion; what
// the method adds to it is flicker).
#include <cstddef>
#include <vector>

namespace host::bench {

struct FlickerMetrics {
    size_t framePairs = 0;
    // Per pixel and channel over every pair of consecutive frames k-1, k:
    //   excess = max(0, |L_k - L_{k-1}| - |R_k - R_{k-1}|)     (L the method, R the reference)
    // mean: sum of excess / sum of |R_k| (the same normalisation as the mean relative error, so
    // the two compare directly); p99, max: the 99th percentile and the largest excess divided by
    // the reference's mean |R_k|.
    double meanExcess = 0, p99Excess = 0, maxExcess = 0;
    // |(L_k - R_k) - (L_{k-1} - R_{k-1})|, the change of the error, normalised the same way. It
    // bounds the excess from above (triangle inequality) and also counts a method whose shafts
    // move differently from the reference's without changing more.
    double meanErrorChange = 0, p99ErrorChange = 0;
    // sum |L_k - L_{k-1}| and sum |R_k - R_{k-1}|, each / sum |R_k|: how much the images change.
    double methodChange = 0, referenceChange = 0;
    // sum |L_k - R_k| / sum |R_k| over every frame (the first included): the mean relative error
    // of the same frames, for the comparison the report makes.
    double meanRelativeError = 0;
    size_t nonFinite = 0;  // NaN or Inf values of the method, over every frame (skipped above)
};

class FlickerMeter {
  public:
    // One frame: `method` RGBA float (as the GPU returns it), `reference` RGB double, the same
    // size every frame.
    void add(const std::vector<float>& method, const std::vector<double>& reference);
    [[nodiscard]] FlickerMetrics result() const;
    // Per pixel, the mean over frame pairs and channels of the excess and of the reference's
    // change |R_k - R_{k-1}| (for a heat map of where the flicker is).
    [[nodiscard]] std::vector<double> excessMap() const { return meanOverPairs(excessMap_); }
    [[nodiscard]] std::vector<double> referenceChangeMap() const {
        return meanOverPairs(referenceMap_);
    }

  private:
    [[nodiscard]] std::vector<double> meanOverPairs(std::vector<double> sums) const;

    std::vector<float> previousMethod_;
    std::vector<double> previousReference_;
    // Every pixel, channel and pair, for the percentiles.
    std::vector<double> excess_, errorChange_;
    std::vector<double> excessMap_, referenceMap_;  // per pixel, summed over pairs
    double sumExcess_ = 0, sumErrorChange_ = 0, sumMethodChange_ = 0, sumReferenceChange_ = 0;
    double sumReferencePaired_ = 0;  // sum |R_k| over the frames k >= 1 (the later of each pair)
    size_t countPaired_ = 0;
    double sumError_ = 0, sumReference_ = 0;
    size_t frames_ = 0, nonFinite_ = 0;
};

}  // namespace host::bench
