#include "screen_share.h"

#include <algorithm>
#include <cmath>

#include "epipolar_constants.h"

namespace ls {
namespace {

// The fewest slices and samples per slice a light's lines keep.
constexpr uint32_t kMinSize = 64;
// A light's sizes halve once its share is this much below the halving's (and double as soon as
// it is above): a share near a step changes no graph from frame to frame.
constexpr double kShrinkMargin = 1.15;

// How many times `full` halves for a share of the whole, keeping `full`'s density: the largest
// k with 2^k * share <= 1, where full / 2^k stays at least kMinSize and a multiple of `grain`.
uint32_t halvings(uint32_t full, uint32_t grain, double share) {
    uint32_t k = 0;
    while (std::ldexp(share, static_cast<int>(k) + 1) <= 1.0) {
        const uint32_t next = full >> (k + 1);
        if (next < kMinSize || (next << (k + 1)) != full || next % grain != 0) break;
        ++k;
    }
    return k;
}

uint32_t halvingsOf(uint32_t full, uint32_t size) {
    uint32_t k = 0;
    while (size != 0 && (size << k) < full) ++k;
    return k;
}

// The halvings for `share`, or the frame before's while the share is not far enough below a new
// step (growing takes effect at once: the lines never thin below the settings' density).
uint32_t keptHalvings(uint32_t full, uint32_t grain, double share, const uint32_t* before) {
    const uint32_t k = halvings(full, grain, share);
    if (before == nullptr || *before >= k) return k;
    return std::max(*before, halvings(full, grain, share * kShrinkMargin));
}

VkRect2D atLeastTwoPixels(VkExtent2D screen, VkRect2D rect) {
    auto widen = [](int32_t& offset, uint32_t& extent, uint32_t size) {
        if (extent >= 2 || size < 2) return;
        extent = 2;
        offset = std::clamp(offset, 0, static_cast<int32_t>(size) - 2);
    };
    widen(rect.offset.x, rect.extent.width, screen.width);
    widen(rect.offset.y, rect.extent.height, screen.height);
    return rect;
}

}  // namespace

LineSizes sizesForRect(const lightscatter::EpipolarSettings& s, VkExtent2D screen, VkRect2D rect,
                       const LineSizes* before) {
    const LineSizes full{s.slices, s.samplesPerSlice};
    if (screen.width == 0 || screen.height == 0) return full;
    rect = atLeastTwoPixels(screen, rect);
    const double w = rect.extent.width, h = rect.extent.height;
    const double W = screen.width, H = screen.height;
    const double perimeter = std::min((w + h) / (W + H), 1.0);
    const double diagonal = std::min(std::sqrt((w * w + h * h) / (W * W + H * H)), 1.0);
    // The march's order needs the samples per slice a multiple of its phases, and the slices a
    // multiple of 4.
    const uint32_t step = marchPhases(s);
    uint32_t slicesBefore = 0, samplesBefore = 0;
    if (before != nullptr) {
        slicesBefore = halvingsOf(full.slices, before->slices);
        samplesBefore = halvingsOf(full.samples, before->samples);
    }
    const uint32_t ks =
        keptHalvings(full.slices, 4, perimeter, before != nullptr ? &slicesBefore : nullptr);
    const uint32_t kn =
        keptHalvings(full.samples, step, diagonal, before != nullptr ? &samplesBefore : nullptr);
    return {full.slices >> ks, full.samples >> kn};
}

glm::vec4 lineBounds(VkExtent2D screen, VkRect2D rect) {
    rect = atLeastTwoPixels(screen, rect);
    const float invW = 1.0f / static_cast<float>(screen.width);
    const float invH = 1.0f / static_cast<float>(screen.height);
    // Written as the shrunk boundary is (-1 + 1/W, 1 - 1/W) so that the whole screen's is the same
    // float: pixel x's centre is -1 + (2 x + 1) / W.
    const auto left = static_cast<float>(rect.offset.x);
    const auto top = static_cast<float>(rect.offset.y);
    const auto right = static_cast<float>(screen.width) -
                       static_cast<float>(rect.offset.x + static_cast<int32_t>(rect.extent.width));
    const auto bottom =
        static_cast<float>(screen.height) -
        static_cast<float>(rect.offset.y + static_cast<int32_t>(rect.extent.height));
    return {-1.0f + (2.0f * left + 1.0f) * invW, -1.0f + (2.0f * top + 1.0f) * invH,
            1.0f - (2.0f * right + 1.0f) * invW, 1.0f - (2.0f * bottom + 1.0f) * invH};
}

}  // namespace ls
