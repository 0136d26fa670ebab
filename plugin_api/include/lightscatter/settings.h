#pragma once
// lightscatter::Settings: the settings every method reads, and each method's own, grouped by
// method (settings.epipolar.slices, settings.planes.count, settings.froxels.tile). Included by
// lightscatter.h. Each field's range, default, profile values and one line of doc are in the
// field tables (lightscatter::settingsFields(), each method's in its own folder): the plugin checks
// a frame's settings against them, and a tool builds its settings file, command line and panel
// from them, so no list of fields is written twice.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "lightscatter/vocabulary.h"  // PlaneTarget
// Each method's own settings (methods.inc names the struct and the member of each).
#include "lightscatter/methods/cone_march.h"
#include "lightscatter/methods/epipolar.h"
#include "lightscatter/methods/froxels.h"
#include "lightscatter/methods/planes.h"

namespace lightscatter {

// A profile decides the fields whose SettingsField::profileSized is set, and only those: epipolar's
// slices and samplesPerSlice, the recommended shadowMapSize, the planes' count and target. The
// figures below are epipolar's slices x samples per slice and the shadow map; each field's table
// holds every profile's value (SettingsField::profileValues).
enum class Profile {
    HighQuality,         // 2048 slices x 1024 samples, 4096^2 shadow map (seed 000)
    Balanced,            // 1024 x 1024, 2048^2
    HighPerformance,     // 1024 x 512, 1024^2
    LowHighQuality,      // the seed's set for weaker devices: 1024 x 1024, 2048^2
    LowBalanced,         // 512 x 512, 1024^2
    LowHighPerformance,  // 512 x 256, 512^2
    Custom,              // Settings as given
};
// The profiles that decide some fields (SettingsField::profileValues): all but Custom.
inline constexpr size_t kSizedProfiles = 6;

enum class ShadowFilter { Nearest, Bilinear };
// The light model the in-scattering integrates (Settings::lightModel). Full: docs/model.md's, with
// transmittance and the phase functions. Simplified: seed 004's (eqs. 2.12-2.17), irradiance
// I / (a1 r^2 + a0) with no transmittance anywhere and an isotropic phase.
enum class LightModel { Full, Simplified };

struct Settings {
    // The profile's recommended shadow map, 0 to 16384 texels on a side (0: none, the lights
    // unshadowed; budget() then needs a size of its own). Only a recommendation,
    // which no method reads: each light's own Light::shadowMapSize decides its map, and a tool
    // (the host's budget and benchmark) sizes its maps by this one.
    uint32_t shadowMapSize = 2048;
    // What every method that samples a shadow map reads.
    ShadowFilter shadowFilter = ShadowFilter::Bilinear;  // 2x2 PCF or nearest texel
    float shadowDepthBias = 0.0f;  // added to the ray's light-space depth before comparing
    // What a frame asks of its method, beyond docs/model.md. Each is honoured by the methods whose
    // MethodInfo says so; the others refuse it, and Auto picks one that honours it.
    // false: seed 003's low-end mode, no shadow-map look-ups (shafts without shadows)
    // (MethodInfo::skipsShadowSampling).
    bool shadowSampling = true;
    // Scrolling noise (seed 002): a density multiplier 1 + a (4 n1 n2 - 1), mean 1, from two
    // samples of a tiling noise texture projected from the light (FrameDescription::noise, or the
    // plugin's own). Art direction the model does not have; amplitude 0 turns it off
    // (MethodInfo::noise).
    float noiseAmplitude = 0.0f;
    // A tile's size: metres (directional) or, for point and spot lights, the tangent of the angle
    // it spans.
    float noiseScale = 1.0f;
    // Tiles per second, two layers (the scroll is taken modulo one tile in double precision).
    std::array<float, 4> noiseVelocity{0.05f, 0.02f, -0.03f, 0.04f};
    // Seed 004's simplified light model (eqs. 2.12-2.17, MethodInfo::simplifiedModel). It drops
    // the transmittance from the light to each point and from each point to the camera, replaces
    // the phase functions by 1/(4 pi) (scattering betaR + betaM) and the light's falloff
    // 1 / (r^2 + r0^2) by 1 / (a1 r^2 + a0); a spot still lights only its cone within its range,
    // and shadows still apply. Its integral along a ray is one arctangent (2.17), cheaper than the
    // model's table, and it is the seed's own model: close to the full one in thin media over short
    // distances, brighter where the medium is dense or the light far (docs/methods.md measures it).
    // The composite still attenuates the engine's color by exp(-betaT S); only Lin changes.
    // a1 = 1 and a0 = light.radius^2 is seed 001's closed form.
    LightModel lightModel = LightModel::Full;
    float simplifiedA0 = 0.0025f;  // a0 (m^2): the default light radius 0.05 m, squared
    float simplifiedA1 = 1.0f;     // a1

    // Each method's own: epipolar, coneMarch, planes, froxels (methods.inc).
#define LIGHTSCATTER_METHOD(Enum, Type, member) Type member;
#define LIGHTSCATTER_METHOD_WITHOUT_SETTINGS(Enum)
#include "lightscatter/methods.inc"
};

// One field of Settings, as its method's table declares it: what a settings file, a command line,
// a benchmark's configuration and a panel need, and the rule the plugin checks it against.
struct SettingsField {
    enum class Kind { Whole, Number, Boolean, Choice, Vector4 };
    // Its name in settings files and messages: the method's member and the field
    // ("epipolar.slices"), or the field alone for Settings' own ("shadowFilter").
    std::string name;
    // Its flat names before version 0.4 ("slices"; "planeCount" and the older "slicePlanes"),
    // which settings files, command lines and benchmark configurations still take for one release.
    std::vector<std::string> formerNames;
    Kind kind = Kind::Number;
    // The values the plugin takes: within [min, max] ((min, max] with minExclusive), and finite;
    // 0 also where zeroIsOff (0 turns the feature off or leaves it to the plugin); a whole number a
    // multiple of multipleOf, or a power of two. A Choice is one of `choices`.
    double min = 0.0, max = 0.0;
    bool minExclusive = false;
    bool zeroIsOff = false;
    uint32_t multipleOf = 1;
    bool powerOfTwo = false;
    std::string rule;  // why the bounds are what they are, as a refusal gives it
    // What a slider offers (a subset of the valid values), and whether over decades.
    double sliderMin = 0.0, sliderMax = 0.0;
    bool logarithmic = false;
    std::vector<std::string> choices;  // Choice: the names, in the enum's order
    // The profiles decide it (all but Custom): each one's value, in Profile's order.
    bool profileSized = false;
    std::array<double, kSizedProfiles> profileValues{};
    std::string doc;  // one line
    // The value as a number: Whole and Number as they are, Boolean 0 or 1, Choice the enum's
    // value, Vector4 the component `component`; and back (a Whole rounded, a Choice truncated).
    std::function<double(const Settings&, int component)> get;
    std::function<void(Settings&, double value, int component)> set;
};

// Named settings of a method, as engines ship it ("froxels-unreal": the froxel grid of Unreal's
// volumetric fog): a name that selects the method and sets some of its fields.
struct MethodPreset {
    std::string name;
    std::string doc;  // one line
    std::function<void(Settings&)> apply;
};

// A figure seed 000 publishes for a profile: its screen, memory (MB) and time (ms) on its GPU.
struct SeedFigure {
    uint32_t screenWidth = 0, screenHeight = 0;
    double megabytes = 0;
    double milliseconds = 0;
};

}  // namespace lightscatter
