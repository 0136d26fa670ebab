// The words the plugin's API, its passes, its shaders and its host share: one enum per concept,
// each value written once. Included by C++ (lightscatter.h, the passes) and by GLSL (through
// shaders/shared/bindings.h), so it holds only #defines outside the C++ block; both preprocessors
// read them alike. Installed beside lightscatter.h; an engine includes lightscatter.h, not this.
#ifndef LIGHTSCATTER_VOCABULARY_H
#define LIGHTSCATTER_VOCABULARY_H

// The values the shaders branch on (frame.glsl's light type and math.glsl's Mie phase).
#define LIGHTSCATTER_LIGHT_DIRECTIONAL 0
#define LIGHTSCATTER_LIGHT_SPOT 1
#define LIGHTSCATTER_LIGHT_POINT 2
#define LIGHTSCATTER_MIE_CORNETTE_SHANKS 0
#define LIGHTSCATTER_MIE_ISOTROPIC 1
#define LIGHTSCATTER_MIE_HAZY 2

#ifdef __cplusplus
namespace lightscatter {

enum class LightType : int {
    Directional = LIGHTSCATTER_LIGHT_DIRECTIONAL,
    Spot = LIGHTSCATTER_LIGHT_SPOT,
    Point = LIGHTSCATTER_LIGHT_POINT,
};

// How a point or spot light's irradiance ends at Light::range. Cut: a hard bound, nothing beyond
// it. Window: KHR_lights_punctual's smooth window, the irradiance times
// clamp(1 - (d / range)^4, 0, 1) at distance d.
enum class RangeFalloff { Cut, Window };

// The Mie lobe: Cornette-Shanks with Medium::g, isotropic, or seed 004's hazy atmosphere
// (1 + 9 cos^16(alpha / 2)) / (8 pi), normalised over the sphere (docs/model.md), which ignores g.
enum class MiePhase : int {
    CornetteShanks = LIGHTSCATTER_MIE_CORNETTE_SHANKS,
    Isotropic = LIGHTSCATTER_MIE_ISOTROPIC,
    Hazy = LIGHTSCATTER_MIE_HAZY,
};

// Where the planes method adds up its planes. Float16: an R16G16B16A16_SFLOAT target, Lin per
// channel; its 11-bit mantissa stops the error falling beyond about 128 planes (docs/methods.md).
// Float32: R32G32B32A32_SFLOAT, twice the memory, converges. Rgba8Channels: seed 002's trick for
// 8-bit blending, monochrome: plane i goes into channel i mod 4 of an R8G8B8A8_UNORM target, the
// four are summed at the end and tinted by the light's and medium's color; each channel holds a
// quarter of Settings::planes.range, and each blend rounds to 1/255 of that.
enum class PlaneTarget { Float16, Float32, Rgba8Channels };
// Its former name, kept so that engines written against it compile. "Slice" no longer names the
// planes: it is an epipolar line in epipolar, a depth slice of the grid in froxels.
using SliceTarget [[deprecated("use PlaneTarget")]] = PlaneTarget;

}  // namespace lightscatter
#endif

#endif
