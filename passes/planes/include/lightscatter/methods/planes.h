#pragma once
// Seed 002's view-aligned planes' own settings, Settings::planes (ranges and docs: its field
// table, lightscatter::settingsFields(), names "planes.*"). The count and the target follow the
// profile (docs/methods.md); the rest is taken from `custom` with every profile. The beam-tree
// methods (seed 004) sample with planes too, placed by `count` and `spacing`. Seed 002 calls its
// planes "slices", and so did this method once (Method::Slices, "slices"; its fields' flat names
// slicePlanes, sliceTarget, ..., then planeCount, planeTarget, ..., still read by settings files
// for one release): "slice" is no word of this method now.
#include <cstdint>

#include "lightscatter/vocabulary.h"  // PlaneTarget

namespace lightscatter {

struct PlanesSettings {
    uint32_t count = 128;  // view-aligned planes across the light's volume
    // Seed 004's dz: the planes set at most this many metres apart along the view axis instead of
    // `count` of them (their count then follows the light's depth extent each frame, 2 to 4096,
    // the spacing shrinking where 4096 do not reach); 0: `count`.
    float spacing = 0.0f;
    PlaneTarget target = PlaneTarget::Float16;
    // The seed's scaling of the count: fewer planes, down to an eighth, as the light's volume
    // shrinks on screen (its depth extent over its distance from the camera).
    bool scaling = false;
    // Rgba8Channels only: the luminance of Lin, in Lin's units, that fills the four channels.
    // 0: from the light and medium (docs/methods.md). Above it the target saturates.
    float range = 0.0f;
    // Rgba8Channels: round each plane's share up or down at random in proportion (stochastic
    // rounding, after the seed's suggestion of interleaved sampling), so that shares under half an
    // 8-bit step still add up; false is the seed's plain rounding, which loses them (banding).
    bool dither = true;
    uint32_t blur = 0;  // seed 002's blur at composite: radius in pixels, 0 off
    // The seed's ambient term beside the inverse square (point and spot lights, 1/m^2): art
    // direction outside docs/model.md, 0 by default.
    float ambient = 0.0f;
};

}  // namespace lightscatter
