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

// The border the lines leave by, in NDC (lo.xy, hi.xy): the centres of the rectangle's outer
// pixels, at least two pixels apart; the whole screen's is seed 000's shrunk boundary.
glm::vec4 lineBounds(VkExtent2D screen, VkRect2D rect);

}  // namespace ls
