#include "screen_share.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

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

// The border slice coordinate (shaders/epipolar/epipolar_geometry.glsl's sliceOfExitPoint) of the
// point where the line from `o` along `d` leaves the border: `o` inside it, or off it with the line
// crossing it (the far crossing, as the unwarp's boundaryRange takes).
double borderSliceOf(glm::dvec2 o, glm::dvec2 d, glm::dvec4 bounds, uint32_t border) {
    const glm::dvec2 lo(bounds.x, bounds.y), hi(bounds.z, bounds.w);
    auto exitAlong = [](double from, double along, double low, double high) {
        if (std::fabs(along) < 1e-300) return 1e300;
        return along > 0.0 ? (high - from) / along : (low - from) / along;
    };
    const double tx = exitAlong(o.x, d.x, lo.x, hi.x), ty = exitAlong(o.y, d.y, lo.y, hi.y);
    const int edge = tx < ty ? (d.x > 0.0 ? 1 : 3) : (d.y > 0.0 ? 2 : 0);
    const glm::dvec2 e = o + std::min(tx, ty) * d;
    double f = 0.0;
    if (edge == 0) f = (e.x - lo.x) / (hi.x - lo.x);
    if (edge == 1) f = (e.y - lo.y) / (hi.y - lo.y);
    if (edge == 2) f = (hi.x - e.x) / (hi.x - lo.x);
    if (edge == 3) f = (hi.y - e.y) / (hi.y - lo.y);
    return (edge + std::clamp(f, 0.0, 1.0)) / 4.0 * border - 0.5;
}

// The directions from `o` to `points` as one angular sector under a half-turn (start and end, in
// the border's order), or none: a point on `o`, or points around it.
struct Sector {
    glm::dvec2 start, end;
};
std::optional<Sector> sectorOf(std::span<const glm::vec2> points, glm::dvec2 o) {
    constexpr double kTurn = 2.0 * std::numbers::pi;
    std::vector<std::pair<double, glm::dvec2>> around;
    for (const glm::vec2& p : points) {
        const glm::dvec2 d = glm::dvec2(p) - o;
        if (!(glm::length(d) > 1e-6)) return std::nullopt;
        around.emplace_back(std::atan2(d.y, d.x), d);
    }
    if (around.empty()) return std::nullopt;
    std::sort(around.begin(), around.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    // The widest gap between neighbours: the points lie within a half-turn from `o` exactly when
    // they leave a gap wider than a half-turn (with a margin for rounding); the sector runs from
    // after it to before it.
    size_t after = 0;
    double gap = 0.0;
    for (size_t i = 0; i < around.size(); ++i) {
        const size_t next = (i + 1) % around.size();
        double g = around[next].first - around[i].first;
        if (next == 0) g += kTurn;
        if (g > gap) {
            gap = g;
            after = next;
        }
    }
    if (!(gap > std::numbers::pi + 1e-3)) return std::nullopt;
    return Sector{around[after].second, around[(after + around.size() - 1) % around.size()].second};
}

// The slices a window of `needed` of the border's takes: the fewest of eighths of the border and
// its halvings below an eighth (at least 64, a multiple of 4) that hold them. Eighths, not only
// halvings: a light off the screen needs three quarters of its border, a halving nothing. Kept
// from the frame before (`before`) while the need is within the margin of it; grown at once.
uint32_t windowSlices(uint32_t border, uint32_t needed, const uint32_t* before) {
    std::vector<uint32_t> steps;
    if (border % 32 == 0)
        for (uint32_t m = 1; m < 8; ++m) steps.push_back(border / 8 * m);
    for (uint32_t k = 1;
         (border >> k) >= kMinSize && ((border >> k) << k) == border && (border >> k) % 4 == 0; ++k)
        steps.push_back(border >> k);
    steps.push_back(border);
    std::sort(steps.begin(), steps.end());
    auto fit = [&](double want) {
        for (uint32_t c : steps)
            if (c >= kMinSize && static_cast<double>(c) >= want) return c;
        return border;
    };
    const uint32_t now = fit(needed);
    if (before == nullptr || *before <= now) return now;
    return std::min(*before, fit(needed * kShrinkMargin));
}

// The angle from `from` to `to`, in (-pi, pi], positive in the border's order.
double turn(glm::dvec2 from, glm::dvec2 to) {
    return std::atan2(from.x * to.y - from.y * to.x, glm::dot(from, to));
}

glm::dvec2 rotated(glm::dvec2 d, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * d.x - s * d.y, s * d.x + c * d.y};
}

}  // namespace

LineWindow lineWindow(std::span<const glm::vec2> cone, glm::vec2 light, glm::vec4 bounds,
                      uint32_t border, const LineWindow* before) {
    const LineWindow whole = wholeBorder(border);
    const glm::dvec2 o(light);
    // A light so far off the screen that its lines are parallel in float: every slice.
    if (!(std::fabs(o.x) < kFarthestLight && std::fabs(o.y) < kFarthestLight)) return whole;
    const bool inside = o.x > bounds.x && o.x < bounds.z && o.y > bounds.y && o.y < bounds.w;
    // The cone's directions from its apex (the corners but the first), where they are a sector.
    std::optional<Sector> sector;
    if (cone.size() >= 2) sector = sectorOf(cone.subspan(1), o);
    if (!inside) {
        // Off the border, only the lines that cross it are valid: the sector of its corners.
        const glm::vec2 corners[4] = {
            {bounds.x, bounds.y}, {bounds.z, bounds.y}, {bounds.z, bounds.w}, {bounds.x, bounds.w}};
        const std::optional<Sector> rect = sectorOf(corners, o);
        if (!rect) return whole;
        if (sector) {
            // Both: their overlap, as angles from the rectangle's start.
            const double width = turn(rect->start, rect->end);
            const double lo = std::max(0.0, turn(rect->start, sector->start));
            const double hi = std::min(width, turn(rect->start, sector->end));
            if (!(lo <= hi)) return whole;  // the cone misses the border (no view ray reaches it)
            sector = Sector{rotated(rect->start, lo), rotated(rect->start, hi)};
        } else {
            sector = rect;
        }
    }
    if (!sector) return whole;
    const glm::dvec4 b(bounds);
    // A pixel between border slices g and g + 1 reads both; two more each side for rounding.
    constexpr int64_t kMargin = 2;
    const auto n = static_cast<int64_t>(border);
    const int64_t first =
        static_cast<int64_t>(std::floor(borderSliceOf(o, sector->start, b, border))) - kMargin;
    const int64_t last =
        static_cast<int64_t>(std::floor(borderSliceOf(o, sector->end, b, border))) + 1 + kMargin;
    const int64_t needed = ((last - first) % n + n) % n + 1;
    if (needed >= n) return whole;
    const uint32_t slices =
        windowSlices(border, static_cast<uint32_t>(needed),
                     before != nullptr && before->border == border ? &before->slices : nullptr);
    if (slices >= border) return whole;
    // Centred: the slices beyond the needed ones, half on each side.
    const int64_t extra = (static_cast<int64_t>(slices) - needed) / 2;
    const int64_t start = first - extra;
    return {static_cast<uint32_t>((start % n + n) % n), border, slices,
            static_cast<uint32_t>(extra), static_cast<uint32_t>(needed)};
}

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
