#pragma once
// Seed 004's occluders as an engine gives them (single precision, metres), checked before the beam
// tree is built from them: each box an oriented box within reach of the shaders' float lengths,
// an inner box inside its outer one. A refusal names the engine's field, occluders[i].outer.axes[0]
// and the like, as the plugin's refusals do.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "occluders.h"

namespace ls::beam {

// An oriented box as given: nothing about it is known yet.
struct GivenBox {
    glm::vec3 center{0.0f};
    std::array<glm::vec3, 3> axes{};
    glm::vec3 halfExtents{0.0f};
};

struct GivenOccluder {
    GivenBox outer;
    std::optional<GivenBox> inner;
};

// The first rule the occluders break (at most `maxCount` of them; each box's axes orthonormal to
// 1e-3, its centre and half extents within `maxLength` metres), or empty when they break none.
std::string refuseOccluders(const std::vector<GivenOccluder>& occluders, size_t maxCount,
                            float maxLength);

// Occluders that refuseOccluders takes, in double with exactly unit axes, for buildLightVolume.
std::vector<Occluder> toOccluders(const std::vector<GivenOccluder>& occluders);

}  // namespace ls::beam
