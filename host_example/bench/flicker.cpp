#include "flicker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "metrics.h"

namespace host::bench {

void FlickerMeter::add(const std::vector<float>& method, const std::vector<double>& reference) {
    const size_t pixels = reference.size() / 3;
    if (method.size() != pixels * 4)
        throw std::logic_error("FlickerMeter: the method's image and the reference differ in size");
    if (frames_ > 0 && reference.size() != previousReference_.size())
        throw std::logic_error("FlickerMeter: a frame's size differs from the first frame's");
    const bool paired = frames_ > 0;
    if (paired && excessMap_.empty()) {
        excessMap_.assign(pixels, 0.0);
        referenceMap_.assign(pixels, 0.0);
    }
    for (size_t p = 0; p < pixels; ++p)
        for (size_t c = 0; c < 3; ++c) {
            const double l = method[p * 4 + c], r = reference[p * 3 + c];
            if (!std::isfinite(l)) {
                ++nonFinite_;
                continue;
            }
            sumError_ += std::fabs(l - r);
            sumReference_ += std::fabs(r);
            if (!paired) continue;
            const double l0 = previousMethod_[p * 4 + c], r0 = previousReference_[p * 3 + c];
            // A pair with a non-finite value has no meaningful change; the value itself was
            // counted above, in its own frame.
            if (!std::isfinite(l0)) continue;
            const double dl = std::fabs(l - l0), dr = std::fabs(r - r0);
            const double excess = std::max(0.0, dl - dr);
            const double errorChange = std::fabs((l - r) - (l0 - r0));
            excess_.push_back(excess);
            errorChange_.push_back(errorChange);
            sumExcess_ += excess;
            sumErrorChange_ += errorChange;
            sumMethodChange_ += dl;
            sumReferenceChange_ += dr;
            sumReferencePaired_ += std::fabs(r);
            ++countPaired_;
            excessMap_[p] += excess / 3.0;
            referenceMap_[p] += dr / 3.0;
        }
    previousMethod_ = method;
    previousReference_ = reference;
    ++frames_;
}

std::vector<double> FlickerMeter::meanOverPairs(std::vector<double> sums) const {
    for (double& v : sums) v /= static_cast<double>(frames_ - 1);
    return sums;
}

FlickerMetrics FlickerMeter::result() const {
    FlickerMetrics m;
    m.framePairs = frames_ > 0 ? frames_ - 1 : 0;
    m.nonFinite = nonFinite_;
    m.meanRelativeError = sumReference_ > 0 ? sumError_ / sumReference_ : 0;
    if (countPaired_ == 0 || sumReferencePaired_ <= 0) return m;
    const double meanReference = sumReferencePaired_ / static_cast<double>(countPaired_);
    m.meanExcess = sumExcess_ / sumReferencePaired_;
    m.meanErrorChange = sumErrorChange_ / sumReferencePaired_;
    m.methodChange = sumMethodChange_ / sumReferencePaired_;
    m.referenceChange = sumReferenceChange_ / sumReferencePaired_;
    m.p99Excess = percentile(excess_, 0.99) / meanReference;
    m.maxExcess = *std::max_element(excess_.begin(), excess_.end()) / meanReference;
    m.p99ErrorChange = percentile(errorChange_, 0.99) / meanReference;
    return m;
}

}  // namespace host::bench
