#include "tonemap.h"

#include <algorithm>
#include <cmath>

namespace host {
namespace {

// The fit reaches 1 at x = 7.24 and stays above it, so clamping x first changes nothing visible;
// unclamped, x * (2.51 x + 0.03) overflows from about 1.2e19 on and inf / inf is NaN (black).
constexpr float kFitSaturates = 64.0f;

float aces(float x) {
    x = std::min(x, kFitSaturates);
    return std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

float srgb(float x) {
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

}  // namespace

std::vector<uint8_t> toneMap(const std::vector<float>& rgba, float exposure) {
    std::vector<uint8_t> out(rgba.size());
    for (size_t i = 0; i < rgba.size(); ++i) {
        float v = 1.0f;
        if (i % 4 != 3) {
            // +Inf is as bright as it gets; NaN has no brightness and shows as black.
            const float scaled = rgba[i] * exposure;
            const float x = std::isnan(scaled) ? 0.0f : std::max(scaled, 0.0f);
            v = srgb(aces(x));
        }
        out[i] = static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    }
    return out;
}

}  // namespace host
