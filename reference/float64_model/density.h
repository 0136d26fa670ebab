#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

namespace ls::ref {

// docs/model.md's height fog: the whole-scene medium's factor h(y) = exp(-k max(0, y - h0)).
struct HeightFog {
    double baseHeight = 0.0;  // h0, metres (world +Y up)
    double falloff = 0.0;     // k >= 0, 1/m
};

// docs/model.md's fog volume: an oriented box whose weight b(x) adds density times itself to m.
struct FogBox {
    glm::dvec3 center{0.0};
    glm::dvec3 halfExtents{1.0};
    // The box's local x, y and z in world space; orthonormal (distances along them are metres).
    std::array<glm::dvec3, 3> axes{{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
    double density = 1.0;  // di >= 0
    double fade = 0.0;     // f >= 0, metres; 0: a hard box

    // x's coordinates along the box's axes, from its centre.
    [[nodiscard]] glm::dvec3 local(const glm::dvec3& x) const;
    // b(x): the product over the axes of clamp((a_j - |local_j|) / f, 0, 1); with f = 0, 1 inside
    // the closed box and 0 outside.
    [[nodiscard]] double weight(const glm::dvec3& x) const;
};

// docs/model.md's density factor m(x) = d0 h(y) + sum_i di b_i(x), which multiplies every
// coefficient of the medium at x. The default is the homogeneous medium of factor 1.
struct Density {
    double base = 1.0;  // d0 >= 0
    std::optional<HeightFog> heightFog;
    std::vector<FogBox> volumes;

    // No height fog and no volumes: m = d0 everywhere.
    [[nodiscard]] bool homogeneous() const { return !heightFog && volumes.empty(); }
    // m = 1 everywhere: the model's homogeneous formulas apply as they are, bit for bit.
    [[nodiscard]] bool unit() const { return homogeneous() && base == 1.0; }
    // m(x).
    [[nodiscard]] double at(const glm::dvec3& x) const;
    // An upper bound of m: d0 + sum_i di (h <= 1 and b_i <= 1).
    [[nodiscard]] double maxDensity() const;
};

}  // namespace ls::ref
