#pragma once
// A light's epipolar lines cover its screen rectangle (LightSetup::screenRect), not the whole
// screen: they leave by the rectangle's border, and its slices and samples per slice follow the
// rectangle's share of the screen, so that a small light's chain costs its share. The settings'
// sizes are the whole screen's; a light's keep their density along the border (the slices, by
// the rectangle's perimeter) and along a line (the samples, by its diagonal), halved while the
// share allows it, so that a light moving across the screen changes its graph only at each halving.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <span>

#include "lightscatter/methods/epipolar.h"

namespace ls {

struct LineSizes {
    uint32_t slices = 0, samples = 0;
    bool operator==(const LineSizes&) const = default;
};

// The sizes of a light whose rays cross the screen within `rect`. `before`: the light's sizes in
// the frame before (null: none), kept until the share has moved past a halving by a margin.
LineSizes sizesForRect(const lightscatter::EpipolarSettings& s, VkExtent2D screen, VkRect2D rect,
                       const LineSizes* before);

// The slices of its border a light's lines take (EpipolarConstants::window). A light off the
// border (off the screen, or behind the camera) has lines only through the rectangle, whose exits
// lie on its far side; a spot seen from outside its cone lights a wedge of the screen from its
// apex, and lines in no other direction carry anything. Its lines need only the border's slices
// whose lines cross that part, at the border's density, so that its chain and (for a frame's
// later light) its unwarp cost the part's share of the screen rather than its rectangle's.
struct LineWindow {
    uint32_t first = 0;   // the first of the border's slices that the lines take
    uint32_t border = 0;  // the slices the border is divided into (sizesForRect's)
    uint32_t slices = 0;  // how many the lines take, from `first` on in the border's order
    // Of those, the ones a lit pixel may read (the rest round the count up to its step): `needed`
    // from the window's slice `neededFrom` on. A later light draws only their wedge.
    uint32_t neededFrom = 0, needed = 0;
    bool part() const { return slices < border; }
    bool operator==(const LineWindow&) const = default;
};
// Every slice of a border of `border`.
inline LineWindow wholeBorder(uint32_t border) {
    return {0, border, border, 0, border};
}
// Farther than this from the screen's centre (NDC), a light's lines are taken as they are: their
// wedge's corners would lose the rasteriser's precision.
inline constexpr double kFarthestLight = 64.0;
// A light's window: `light` its screen point and `bounds` its lineBounds, both NDC; `cone` a spot's
// lightScreenCorners (apex first), or empty. The border's slices that the directions from the
// light to the cone's corners cross (within the border's own directions, for a light off it), two
// more each side, in eighths of the border or its halvings below an eighth (at least 64 slices, a
// multiple of 4, shrunk only once the need is past a step by a margin, as sizesForRect's, and
// grown at once); the whole border
// where neither bounds them (a light on the screen without a cone; corners that surround the
// light: the camera inside the cone). `before`: the frame before's (null: none).
LineWindow lineWindow(std::span<const glm::vec2> cone, glm::vec2 light, glm::vec4 bounds,
                      uint32_t border, const LineWindow* before);

// The border the lines leave by, in NDC (lo.xy, hi.xy): the centres of the rectangle's outer
// pixels, at least two pixels apart; the whole screen's is seed 000's shrunk boundary.
glm::vec4 lineBounds(VkExtent2D screen, VkRect2D rect);

}  // namespace ls
