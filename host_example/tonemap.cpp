#include "tonemap.h"

#include <algorithm>
#include <cmath>

namespace host {
namespace {

float aces(float x) {
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
            const float x = std::isfinite(rgba[i]) ? std::max(rgba[i] * exposure, 0.0f) : 0.0f;
            v = srgb(aces(x));
        }
        out[i] = static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    }
    return out;
}

}  // namespace host
