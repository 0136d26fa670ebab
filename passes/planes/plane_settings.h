#pragma once
// Seed 002's view-aligned planes, as the placement takes them (the planes method; the beam trees
// sample with them too, from here).
#include <cstdint>
#include <glm/glm.hpp>

namespace ls {

struct PlaneSettings {
    bool operator==(const PlaneSettings&) const = default;
    uint32_t planes = 128;
    float spacing = 0.0f;         // seed 004's dz (metres, at most): the count follows; 0: planes
    bool planeScaling = false;    // seed 002: fewer planes as the light's volume recedes
    bool eightBitTarget = false;  // the range below only matters to the 8-bit channel target
    float range = 0.0f;           // 8-bit target: Lin luminance at full scale; 0: estimated
    float ambient = 0.0f;
    float noiseAmplitude = 0.0f;
    float noiseScale = 1.0f;
    glm::vec4 noiseVelocity{0.0f};
};

}  // namespace ls
