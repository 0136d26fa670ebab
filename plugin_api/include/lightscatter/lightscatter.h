#pragma once
// lightscatter: volumetric light scattering (light shafts) as a post-process on Vulkan 1.3.
//
// The one header an engine includes (C++17 or later). The engine imports its depth, color and
// (optionally) shadow-map images, describes the camera, the light and the medium in the units of
// docs/model.md (metres, W/m^2, W/sr, 1/m), picks a method and a quality profile, and gets its
// color image back composited:
//     color = color * exp(-betaT * S) + k * Lin
// with S the distance along each pixel's ray to the surface (or to the sky distance), Lin the
// single-scattered in-scattering and k the engine's pre-exposure (FrameDescription::preExposure,
// 1 by default). Nothing else is done to the color: no tone mapping.
//
// Requirements on the engine's VkInstance and VkDevice: Vulkan 1.3 (the instance created with
// VkApplicationInfo::apiVersion 1.3 or later, told to the plugin in VulkanContext::apiVersion, on
// a physical device that offers 1.3), the extensions requiredDeviceExtensions() lists
// (VK_KHR_push_descriptor) and the features requiredDeviceFeatures() turns on (synchronization2,
// dynamicRendering, maintenance4; separateDepthStencilLayouts, hostQueryReset;
// shaderStorageImageExtendedFormats, shaderClipDistance, fragmentStoresAndAtomics). The engine
// tells the plugin what it enabled (VulkanContext::enabledFeatures), and the plugin refuses a
// device that lacks one. missingDeviceFeatures() says what a physical device lacks, before the
// engine makes a device of it. Optional: dualSrcBlend, asked for by requiredDeviceFeatures() of a
// physical device that has it; never required.
//
// Linking: CMake target lightscatter::plugin, from find_package(lightscatter CONFIG) on an
// installed tree or from add_subdirectory on the source tree. The guide: docs/integration.md.
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "lightscatter/limits.h"      // the ranges of a frame's numbers
#include "lightscatter/settings.h"    // Settings, Profile, each method's settings
#include "lightscatter/vocabulary.h"  // LightType, MiePhase, PlaneTarget

// The library's version. 0.x: a minor version may change the API, so an engine compiles against the
// header of the library it links. lightscatter::version() returns the library's at run time; a
// header and a library of different major.minor versions do not link (Plugin's constructor takes
// a tag named for the header's version, which only the library of that version defines).
#define LIGHTSCATTER_VERSION_MAJOR 0
#define LIGHTSCATTER_VERSION_MINOR 6
#define LIGHTSCATTER_VERSION_PATCH 0

// What the library exports: everything declared with LIGHTSCATTER_API (a shared build exports
// nothing else).
#if defined(_WIN32)
#if defined(LIGHTSCATTER_BUILDING_SHARED)
#define LIGHTSCATTER_API __declspec(dllexport)
#elif defined(LIGHTSCATTER_SHARED)
#define LIGHTSCATTER_API __declspec(dllimport)
#else
#define LIGHTSCATTER_API
#endif
#else
#define LIGHTSCATTER_API __attribute__((visibility("default")))
#endif

namespace lightscatter {

struct Version {
    uint32_t major = 0, minor = 0, patch = 0;
};
// The library's version (the header's is LIGHTSCATTER_VERSION_*).
LIGHTSCATTER_API Version version();

using Vec3 = std::array<float, 3>;
using Mat4 = std::array<float, 16>;  // column-major (GLM's layout), maps column vectors

// The ranges of a frame's numbers: lightscatter/limits.h.

// The methods (docs/methods.md), one per line of lightscatter/methods.inc, in its order: epipolar
// sampling (seed 000), brute-force per-pixel marching (the GPU reference), seed 001's arctangent
// closed form (unshadowed point and spot lights), seed 003's cone-limited fixed-count march, seed
// 002's view-aligned planes, seed 004's two methods (a beam tree of FrameDescription::occluders,
// built on the CPU each frame, splits a point or spot light's volume into lit, uncertain and dark
// space; dark space is never drawn. BeamTreeAnalytic integrates lit space in closed form and
// samples uncertain space with seed 002's planes and the shadow map; BeamTreeSampling samples both
// with the planes, skipping the shadow map in lit space), and the froxel volumetric fog engines
// ship (Unreal, Frostbite, HDRP, Godot), for comparison on the same frame: every light of the frame
// injected into one view-frustum grid (Settings::froxels), integrated front to back, applied at
// each pixel's depth. methodInfo() says what each takes. Auto picks one per light and frame from
// what the frame holds and says which and why in the FrameReport.
enum class Method {
#define LIGHTSCATTER_METHOD(Enum, Type, member) Enum,
#define LIGHTSCATTER_METHOD_WITHOUT_SETTINGS(Enum) Enum,
#include "lightscatter/methods.inc"
    Auto,
    // The planes method's former name ("slices" too is still parsed), kept so that engines
    // written against it compile. "Slice" no longer names the planes: it is an epipolar line in
    // epipolar (settings.epipolar.slices) and a depth slice of the grid in froxels
    // (settings.froxels.slices).
    Slices [[deprecated("use Method::Planes")]] = Planes,
};

LIGHTSCATTER_API const char* methodName(Method m);    // "epipolar", "brute-force", "analytic", ...
LIGHTSCATTER_API const char* profileName(Profile p);  // "high-quality", "balanced", ... "custom"
// A method's name, or a former one: "slices" is Method::Planes.
LIGHTSCATTER_API std::optional<Method> parseMethod(const std::string& name);
LIGHTSCATTER_API std::optional<Profile> parseProfile(const std::string& name);
LIGHTSCATTER_API std::vector<std::string> methodNames();
LIGHTSCATTER_API std::vector<std::string> profileNames();

// What a method is and takes (a tool lists the methods, their settings and their capabilities from
// it; the plugin's refusals name methods from it).
struct MethodInfo {
    Method method = Method::Auto;
    std::string name;         // methodName(method)
    std::string description;  // one line
    // The lights it takes, and what of them.
    bool directional = true, spot = true, point = true;
    bool shadowMap = true;             // casts shadows from a light's shadow map
    bool cubeShadow = false;           // samples a point light's six-face shadow map
    bool lightColor = true;            // a light-space color (cookie) with a shadow map
    bool unshadowedLightColor = true;  // ... and without one
    // Settings it honours beyond docs/model.md (the others refuse them).
    bool noise = false;                // Settings::noiseAmplitude > 0
    bool simplifiedModel = false;      // Settings::lightModel = Simplified
    bool skipsShadowSampling = false;  // Settings::shadowSampling = false
    bool readsOccluders = false;       // FrameDescription::occluders
    // A non-uniform medium (Medium::heightFog, Medium::fogVolumes); every method takes a
    // homogeneous one.
    bool media = false;
    // Every light of the frame goes into one chain of its nodes (froxels' grid): it mixes with no
    // other method in a frame.
    bool onePerFrame = false;
    bool exportsVolume = false;  // writes FrameDescription::volumeOut
    bool keepsHistory = false;   // a frame's output may depend on earlier frames'
    bool countsSteps = false;    // DebugOptions::countSteps counts its march
    // Its textures depend on the profile (its budget() is worth comparing across profiles).
    bool profileSized = false;
    std::vector<SettingsField> settings;  // its own fields (Settings::<member>), or none
    std::vector<MethodPreset> presets;    // named settings of it, or none
};
// Every method, in the enum's order (Auto is none of them).
LIGHTSCATTER_API const std::vector<MethodInfo>& methodInfo();
// Every field of Settings: its own first (the shared ones), then each method's, in methodInfo()'s
// order.
LIGHTSCATTER_API const std::vector<SettingsField>& settingsFields();
// The field of that name (SettingsField::name) or former name; null when there is none.
LIGHTSCATTER_API const SettingsField* findSettingsField(const std::string& name);
// A preset's method and settings (MethodInfo::presets): sets its fields in `settings` and returns
// its method; nothing for a name that is no preset.
LIGHTSCATTER_API std::optional<Method> applyMethodPreset(const std::string& name,
                                                         Settings& settings);

// Checks settings against their fields' rules (settingsFields()), as record() does: throws
// InvalidInput naming the first field outside its rule, as `at`.name ("custom.epipolar.slices";
// the name alone when `at` is empty), and the rule.
LIGHTSCATTER_API void checkSettings(const Settings& settings, const std::string& at = "custom");

// The settings of a profile (Custom returns the defaults). A value that is no Profile throws
// InvalidInput naming `profile` (it would otherwise silently be Custom).
LIGHTSCATTER_API Settings profileSettings(Profile profile);
// The settings a frame with this profile and `custom` runs with: `custom`, with the profile's
// values of the fields it decides (SettingsField::profileSized) where the profile is not Custom.
LIGHTSCATTER_API Settings profileSettings(Profile profile, const Settings& custom);

// The camera that rendered `depth`. The projection is the one authority on the depth buffer: the
// plugin reads the near and far planes from it (the view-space distances it maps to depth 0 and 1),
// so they cannot disagree with what the depth buffer holds.
struct Camera {
    // World -> view (right-handed, looks down -Z): a rotation and a translation (to 1e-3), the
    // camera's position within limits::kMaxLength of the origin on each axis.
    Mat4 view{};
    // View -> Vulkan clip (y down, depth in [0, 1]), perspective: GLM's perspective needs [1][1]
    // negated (one with clip y up, P[1][1] > 0, is refused). Its w row (P[0][3], P[1][3], P[2][3],
    // P[3][3]) is (0, 0, -1, 0) times a positive scale, clip w the distance along the view axis:
    // an orthographic projection (w row 0 0 0 1), whose rays are parallel, is refused. Its field of
    // view on each axis lies in [limits::kMinFovDegrees, limits::kMaxFovDegrees], its near plane at
    // limits::kMinNearPlane or more and its far plane at limits::kMaxLength or less; with
    // standard depth, or a D16/D24 depth buffer, the far plane (or with an infinite far plane
    // medium.maxDistance) is at most 2^b / limits::kDepthStepsPerDistance times the near plane
    // (b: 24, or 16 for D16; limits says why).
    Mat4 projection{};
    // Optional, in metres. 0 (the default): taken from the projection. When set, each must agree
    // with the projection (to 0.1%, more where float32 cannot resolve the far plane), or the frame
    // is refused: a projection built for another far plane would silently move the sky and the fog.
    float nearPlane = 0.0f;
    float farPlane = 0.0f;     // ignored when infiniteFar
    bool reversedZ = false;    // depth 1 at the near plane; must match the projection
    bool infiniteFar = false;  // no far plane (the sky is medium.maxDistance away); must match it
};

struct Light {
    LightType type = LightType::Directional;
    // Point, spot; each in [-limits::kMaxLength, kMaxLength]. Where a spot's shadowViewProjection
    // is used (a shadow map, or a light color), the apex of that matrix (the point it maps to clip
    // x = y = w = 0): within 1e-3 of the light's reach (the nearer of its range and the matrix's
    // far plane, or 1000 times its near plane where it has no far plane, limits::kMaxLength where
    // it has neither) plus 1e-5 of the position's distance from the origin (float32's rounding of
    // the matrix), or the frame is refused naming light.position.
    Vec3 position{0, 0, 0};
    // Direction light travels (directional), cone axis (spot): finite, not zero (normalised in
    // double precision, so any such length will do). Where shadowViewProjection is used, along its
    // axis to 0.1 degrees, or the frame is refused naming light.direction: a spot's, the
    // direction from the apex to the centre of clip space; a directional light's, the direction
    // along which clip x and y stay, signed the way depth grows (falls with shadowReversedZ) with
    // a shadow map, either way with a light color alone.
    Vec3 direction{0, -1, 0};
    // E (W/m^2) for directional, I (W/sr) for point and spot; each in [0, limits::kMaxIntensity].
    Vec3 intensity{1, 1, 1};
    // A spot's cone, as KHR_lights_punctual (and Unreal, Godot, Bevy, Filament) define it: full
    // intensity within innerConeAngleDegrees of the axis, then the angular falloff
    // a = clamp((cos t - cos outer) / (cos inner - cos outer), 0, 1)^2 (t the angle from the axis)
    // to 0 at outerConeAngleDegrees; inner = outer is a hard edge (a step). 89 degrees at most,
    // not KHR's 90: the methods clip a ray to the cone's lit nappe, which is convex only below 90
    // degrees, and at 90 its quadric degenerates to a plane. Each in
    // [limits::kMinConeAngleDegrees, 89], inner <= outer. With a shadow map, the cone of the
    // outer angle lies inside shadowViewProjection's frustum (its four sides, x = +-w and y = +-w
    // in clip space), passing none by more than 0.01 degrees, or the frame is refused naming
    // light.outerConeAngleDegrees (KHR's angle is the half angle: a frustum's full field of view
    // is twice it).
    float innerConeAngleDegrees = 30;
    float outerConeAngleDegrees = 30;
    // Point and spot: how far the light reaches (metres; 1e30: no range), ended as rangeFalloff
    // says. > 0 and finite (only compared).
    float range = 1e30f;
    RangeFalloff rangeFalloff = RangeFalloff::Cut;
    float radius = 0.05f;  // r0 of docs/model.md, in [limits::kMinRadius, kMaxLength]
    // The shadow map's projection (world -> light clip, Vulkan conventions) and size. Required with
    // a directional or spot light's shadow map (a singular matrix, such as the all-zero default, is
    // refused); for a spot its frustum must contain the cone. Also required with a light color
    // and no shadow map: the color is projected with it (its sides; no near or far plane). Ignored
    // for a point light, and for a light with neither (a spot without a shadow map may leave it
    // as it is). Where it is used it must be this light's, as the frame shows it: a spot's a
    // perspective projection from `position` along `direction`, a directional light's one along
    // `direction` (position, direction and outerConeAngleDegrees state the tolerances).
    Mat4 shadowViewProjection{};
    // A point light's cube shadow map (FrameDescription::shadowMap with 6 array layers, each
    // shadowMapSize x shadowMapSize): the world -> clip matrix of each face, in Vulkan's cube
    // layer order +X, -X, +Y, -Y, +Z, -Z (index = layer). Each face is a 90-degree square frustum
    // with its apex at `position`, looking along its world axis, oriented as Vulkan samples a cube
    // (the specification's "Cube Map Face Selection" table): a direction d from the light whose
    // major axis is the face's lands at clip x/w = sc / |ma|, y/w = tc / |ma| with
    //     +X: sc = -d.z, tc = -d.y     -X: sc = +d.z, tc = -d.y
    //     +Y: sc = +d.x, tc = +d.z     -Y: sc = +d.x, tc = -d.z
    //     +Z: sc = +d.x, tc = -d.y     -Z: sc = -d.x, tc = -d.y
    // (Vulkan clip y points down the image: row 0 is y/w = -1.) With a GL-style perspective (clip y
    // up, depth [0, 1], not flipped for Vulkan) that is lookAt(position, position + axis, up) with
    // up -Y for the X and Z faces, +Z for +Y and -Z for -Y: the classic cube-map cameras. Depth is
    // z/w in [0, 1] increasing away from the light, or decreasing with shadowReversedZ, as for a
    // spot's map; near and far planes are the engine's. Every face is checked (to 1e-3 in clip
    // x/w, y/w): a singular matrix, a frustum that is not centred on its axis at the light, a
    // field of view other than 90 degrees, a mirrored face or depth against shadowReversedZ is
    // refused naming light.cubeFaceViewProjections[i]. Every method that casts shadows samples
    // a cube shadow map (epipolar face by face, the others per point); analytic refuses it.
    std::array<Mat4, 6> cubeFaceViewProjections{};
    uint32_t shadowMapSize = 0;  // 0: no shadow map
    bool shadowReversedZ = false;
};

// Height fog (docs/model.md, "Non-uniform media"): the whole-scene medium's density is
// exp(-falloff max(0, y - baseHeight)) of its own at a world height y (+Y up): full at and below
// the base height, falling off exponentially above it (HDRP's fog, Unreal's exponential height
// fog above its fog height).
struct HeightFog {
    float baseHeight = 0.0f;  // metres; |baseHeight| <= limits::kMaxLength
    float falloff = 0.0f;     // 1/m, in [0, limits::kMaxFogFalloff]; 0: a uniform medium
};

// A local fog volume (docs/model.md): an oriented box whose density adds to the whole-scene
// medium's, with the same coefficients (it is denser or thinner medium, not another medium: no
// albedo or phase of its own). Its weight is 1 inside and 0 outside, or, with fade > 0, the
// product over its three axes of clamp((halfExtent - |local|) / fade, 0, 1).
struct FogVolume {
    Vec3 center{0, 0, 0};  // world, metres; each |coordinate| <= limits::kMaxLength
    // Metres, each in [0, limits::kMaxLength].
    Vec3 halfExtents{1, 1, 1};
    // The box's local x, y and z in world space: unit length and orthogonal to each other within
    // 1e-3 (a rotation or a reflection; a matrix with scale is refused: put it in halfExtents).
    std::array<Vec3, 3> axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    float density = 1.0f;  // added to the medium's factor inside; in [0, limits::kMaxDensity]
    float fade = 0.0f;     // metres, in [0, limits::kMaxLength]; 0: a hard edge
};

struct Medium {
    // Each channel of betaR, betaM and sigmaA in [0, limits::kMaxCoefficient].
    Vec3 betaR{5.8e-6f, 13.5e-6f, 33.1e-6f};  // Rayleigh scattering, 1/m
    Vec3 betaM{2e-5f, 2e-5f, 2e-5f};          // Mie scattering, 1/m
    float g = 0.76f;                          // Mie asymmetry, (-1, 1)
    Vec3 sigmaA{0, 0, 0};                     // absorption, 1/m
    MiePhase phase = MiePhase::CornetteShanks;
    // Sky distance with an infinite far plane, m; in (0, limits::kMaxLength].
    float maxDistance = 1000.0f;
    // A non-uniform medium (docs/model.md): the coefficients above are multiplied at each point x
    // by m(x) = density h(y) + sum over fogVolumes of volume.density times its weight at x, with
    // h the height fog's factor (1 without one). The densest point's coefficients, (density + the
    // volumes' densities) times the largest coefficient, must stay within kMaxCoefficient.
    // Defaults: exactly the homogeneous medium. A medium without height fog or volumes is
    // homogeneous whatever its density (every method takes it, at its homogeneous cost); height
    // fog or a volume is taken by the methods whose methodInfo() says `media` (analytic and
    // beam-tree-analytic refuse it). Fog parameters may change every frame without compiling;
    // giving height fog or volumes where a frame had none (or none where it had) compiles once.
    float density = 1.0f;  // d0, in [0, limits::kMaxDensity]
    std::optional<HeightFog> heightFog;
    std::vector<FogVolume> fogVolumes;  // at most limits::kMaxFogVolumes
};

// Units for an engine whose lights carry none (a light of intensity 1 lights a white surface facing
// it to 1, as N.L shading does): the intensity a light needs for a shaft of a chosen brightness.
// The plugin's lights are physical (Light::intensity: W/sr, or W/m^2 for a directional light), and
// a shaft is the light scattered towards the camera along the stretch of a view ray inside the
// beam, so a light bright enough for a surface is often far too dim for its shaft: seen across a
// 1 m wide beam through betaM = 0.01/m (g = 0.76), the shaft sends about 1e-4 of the irradiance it
// crosses towards the camera, where a white surface returns 1/pi of it. Choose where a shaft
// should be seen and how bright, and give the plugin's light this intensity (times the light's
// color): the engine's own shading of the light stays as it is.
struct ShaftGoal {
    float brightness = 0.05f;    // Lin wanted at the shaft, in the engine's color units (> 0)
    float beamWidth = 1.0f;      // metres of lit beam the view ray crosses (> 0)
    float viewDistance = 10.0f;  // metres from the camera to the shaft (>= 0)
    float lightDistance = 5.0f;  // point, spot: metres from the light to the shaft (> 0)
    // docs/model.md's scattering angle t: 0 looking into the light, 90 across its beam.
    float scatteringAngleDegrees = 90.0f;
    float radius = 0.05f;  // point, spot: Light::radius (r0)
};
// Per channel: the intensity (I for a point or spot light, E for a directional one) that makes the
// shaft's Lin equal goal.brightness under docs/model.md's single scattering, the irradiance taken
// as constant across the beam:
//     Lin = P(t) Irr exp(-betaT viewDistance) (1 - exp(-betaT beamWidth)) / betaT
//     Irr = I exp(-betaT lightDistance) / (lightDistance^2 + radius^2)   (point, spot)
//     Irr = E                                                           (directional)
// A spot's cone falloff and a shadow are not in it: aim at the inside of the cone. Throws
// InvalidInput naming the goal's field that breaks its rule, or when the medium scatters nothing or
// the intensity needed is above limits::kMaxIntensity.
LIGHTSCATTER_API Vec3 shaftIntensity(LightType type, const Medium& medium, const ShaftGoal& goal);

// An engine image handed to the plugin for one frame: where it stands and where it must be left.
// The plugin uses mip level 0 and array layers 0 to arrayLayers - 1; it never keeps the image
// beyond the frame's commands, and never names it (the engine's debug name stays).
//
// Within record(), the plugin's first command on the image is a barrier from (stages, access,
// layout) to its own use, and its last a barrier from its own use to (finalStages, finalAccess,
// finalLayout). The fields:
//
// - image:
//     One VkImage may fill several roles of a frame only where the plugin reads it in each
//     (shadow maps, light colors, noise) and each gives SHADER_READ_ONLY_OPTIMAL as its layout
//     and finalLayout (two lights sharing a shadow map). An image the plugin writes (color,
//     inscatterOut, transmittanceOut, volumeOut) in a second role, one image in two layouts or in
//     another layout, or a depth with DEPTH_STENCIL_ATTACHMENT usage (which the plugin may
//     depth-test in a depth layout) in a second role is refused naming both fields: the plugin
//     would read what it writes, or one role's barriers would move the image out of the layout
//     the other's expect.
// - format:
//     One the device can use as the role needs (vkGetPhysicalDeviceFormatProperties, optimal
//     tiling), or the frame is refused naming the field: SAMPLED_IMAGE for the depth and shadow
//     maps, a color format with SAMPLED_IMAGE_FILTER_LINEAR for lightColor and noise (sampled
//     with a linear filter: a depth or integer format is refused), STORAGE_IMAGE for the outputs
//     and a storage color; each field's own formats are said where it is declared.
// - usage:
//     The VkImageUsageFlags the image was created with. The plugin needs SAMPLED (depth,
//     shadowMap, lightColor) or STORAGE (color, inscatterOut); layouts are checked against these
//     flags (COLOR_ATTACHMENT_OPTIMAL needs COLOR_ATTACHMENT, ...).
// - layout:
//     The layout the image is in when the plugin's commands start. It must be a layout the
//     image's format and usage can hold (a depth image cannot be in COLOR_ATTACHMENT_OPTIMAL).
//     UNDEFINED only for inscatterOut, which the plugin overwrites; the other images are read.
// - stages, access:
//     The pipeline stages and access types of the engine's last use before the plugin (for
//     example LATE_FRAGMENT_TESTS + DEPTH_STENCIL_ATTACHMENT_WRITE after a depth pass). The
//     plugin's first barrier waits for them. The defaults wait for everything.
// - arrayLayers:
//     The layers the plugin reads and transitions (0 to arrayLayers - 1), all in `layout` at the
//     start and left in `finalLayout`: 1 for every image but a point light's shadow map, which
//     has 6 (its cube faces, Light::cubeFaceViewProjections; an image created cube-compatible or
//     a plain 2D array, sampled as a 2D array).
// - depth:
//     A 3D image's extent in z (volumeOut); 1 for every other image.
// - finalLayout:
//     The layout the plugin leaves the image in (required; not UNDEFINED or PREINITIALIZED).
// - finalStages, finalAccess:
//     The engine's next use after the plugin: the plugin's last barrier makes its work visible to
//     them. The defaults make it visible to everything.
//
// Stages and the VkImage handle may change from frame to frame at no cost. A different format,
// extent (a resize), usage or layout selects another frame graph on the next record(): one
// compiled the first time that configuration is met and kept after (the last 8), its textures in
// the plugin's one transient heap, which grows to the largest graph's; nothing waits for the GPU,
// and what the old graph used is destroyed once the frames that used it have completed. With
// PluginCreateInfo::maxRenderSize, a size within it selects nothing new at all.
struct ImageInput {
    VkImage image = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{0, 0};
    VkImageUsageFlags usage = 0;                       // the flags the image was created with
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // at the start of the frame
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;  // the engine's last use
    VkAccessFlags2 access = VK_ACCESS_2_MEMORY_WRITE_BIT;
    VkImageLayout finalLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // required
    VkPipelineStageFlags2 finalStages =
        VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;  // the engine's next use
    VkAccessFlags2 finalAccess = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
    uint32_t arrayLayers = 1;  // 6 for a point light's cube shadow map, else 1
    uint32_t depth = 1;        // a 3D image's extent in z (volumeOut), else 1
};

// Seed 004's occluders: bounding volumes of the scene's objects, in world space (metres), from
// which the beam-tree methods work out on the CPU which parts of a point or spot light's volume are
// certainly lit, uncertain or certainly dark. An oriented box: `axes` orthonormal (to 1e-3),
// `halfExtents` > 0 along them.
struct OccluderBox {
    Vec3 center{0, 0, 0};
    std::array<Vec3, 3> axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    Vec3 halfExtents{0.5f, 0.5f, 0.5f};
};
// `outer` encloses the object (every part of it is inside); `inner`, when given, lies inside the
// object (every point of it is inside the object's solid), so light that reaches it stops there.
// Boxes of different occluders must not overlap (seed 004 inserts them nearest first).
struct Occluder {
    OccluderBox outer;
    std::optional<OccluderBox> inner;
};
inline constexpr size_t kMaxOccluders = 4096;
// FrameDescription::lights holds at most this many. Each light costs its own work and memory: a
// chain of its own (its passes, its shadow map's trees; a one-per-frame method's lights share one
// chain, but each is injected on its own), and for a point or spot light whose method reads one
// its 512x256 RGBA32F table (2 MiB, kept across frames while the light is in use), so the cost
// grows with each light; more are refused rather than exhausting the device (10,000
// lights took the machine's memory).
inline constexpr size_t kMaxLights = 64;

// Debugging aids, off by default and free when off.
struct DebugOptions {
    // Every transient texture and buffer of the plugin is filled with NaN (float formats) or all
    // ones (integer formats) at its first use in each frame, before the pass that first uses it.
    // Transients share memory; an output free of NaN then shows that no pass read what another
    // resource left behind. The environment variable LS_POISON_TRANSIENTS=1 turns it on for every
    // frame of every plugin in the process.
    bool poisonTransients = false;
    // Counts what epipolar's ray march does (FrameReport::steps): the march runs a variant of its
    // shader that adds each ray's counts into a small buffer, read back with the frame's times.
    // Off, the plain shader runs (no buffer, no atomics). Epipolar frames only (also when Auto
    // picks epipolar); the other methods ignore it. Turning it on or off rebuilds the frame graph.
    bool countSteps = false;
};

// One light of a frame of several (FrameDescription::lights): the light and its own images, with
// the meaning and rules of FrameDescription::light, shadowMap and lightColor.
struct LightInput {
    Light light;
    std::optional<ImageInput> shadowMap;  // the light's depth (sampled); 6 layers for a point light
    std::optional<ImageInput> lightColor;  // optional light-space color (stained glass), sampled
    // This light's own settings (for instance profileSettings(Profile::HighPerformance) for a small
    // spot beside a high-quality sun): its chain uses them as if the frame's profile were Custom
    // with these, checked by the same rules (errors name lights[i].settings.field). Without them
    // the light takes the frame's profile and custom. budget() assumes one profile for every light.
    std::optional<Settings> settings;
    // This light's method. Auto follows FrameDescription::method: a frame's Auto chooses for each
    // light on its own (FrameReport::lights says what and why); any other value overrides the
    // frame's method for this light alone, and is refused, naming lights[i], where it cannot honour
    // the light.
    Method method = Method::Auto;
    // The light's identity, chosen by the engine (a key of its own that stays with the light, such
    // as an entity id). The plugin keeps the light's state across frames under it (its point-light
    // table, its method's data) and orders the frame's lights by it, so that the same lights in
    // another order render the same frame bit for bit and compile nothing, and a light leaving the
    // list takes its state with it and leaves the others' untouched. Absent: the light's position
    // in the list, so that without ids a reordered list is other lights to the plugin (their
    // state moves with the positions, and the frame may compile). The lights of a frame have
    // different ids (a frame giving one twice is refused naming both). The state of a light absent
    // for framesInFlight + 60 frames is released: memory follows the lights in use, and a light
    // that comes back after that starts anew, as on its first frame.
    std::optional<uint64_t> id;
};

struct FrameDescription {
    ImageInput depth;  // D16/D24/D32 (sampled); the camera's depth
    // The engine's color, which the plugin composites into: color * exp(-betaT S) + k Lin (k the
    // preExposure below). Two ways, chosen by its format and usage:
    //   - R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT with STORAGE usage: the passes that make Lin
    //     read-modify-write it where they make it (no pass of its own; the faster path).
    //   - any other format the device blends into as a color attachment (COLOR_ATTACHMENT usage,
    //     VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT): B10G11R11_UFLOAT_PACK32,
    //     A2B10G10R10_UNORM_PACK32, the float formats without STORAGE, 8-bit UNORM and SRGB. The
    //     passes write k Lin and the transmittance into two screen textures of the plugin's, and a
    //     graphics pass of its own blends them in (one draw with dualSrcBlend enabled on the
    //     device, two without), outside any render pass of the engine's. An SRGB target blends in
    //     linear (the hardware converts); a UNORM target's values are taken as the engine's linear
    //     values, and the format clamps the result to [0, 1] as it stores it.
    // Absent (format VK_FORMAT_UNDEFINED): the engine composites itself from inscatterOut and
    // transmittanceOut, which are then required.
    ImageInput color;
    std::optional<ImageInput> shadowMap;  // the light's depth (sampled); 6 layers for a point light
    // Optional light-space color (a cookie, stained glass; sampled, linear values in [0, 1], e.g.
    // an R8G8B8A8_SRGB image): multiplies a spot's or directional light's irradiance where
    // light.shadowViewProjection projects each point, with a shadow map or without one (then
    // epipolar and brute-force march it per pixel, a piece per texel crossed; analytic and
    // beam-tree-analytic refuse it; docs/methods.md, "Cookies"). Refused with a point light.
    std::optional<ImageInput> lightColor;
    std::optional<ImageInput> inscatterOut;  // optional: Lin alone, R32G32B32A32_SFLOAT storage
    // Optional: the transmittance from the camera to each pixel's depth, per channel (rgb; a = 1):
    // exp(-betaT S), or froxels' grid's. With inscatterOut, what an engine that composites itself
    // needs: color * T + k Lin. R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT, storage, depth.extent.
    std::optional<ImageInput> transmittanceOut;
    // Optional, with froxels: the frame's integrated grid, for an engine to fog what the depth
    // buffer does not hold (forward transparents, particles). A 3D R16G16B16A16_SFLOAT storage
    // image of froxelVolume()'s width x height x depth; each texel holds Lin (rgb, unexposed,
    // capped at 65504) and the transmittance (a) from the camera to its froxel's far end. A frame
    // whose method is not froxels refuses it.
    std::optional<ImageInput> volumeOut;
    // Optional tiling noise for Settings::noiseAmplitude (sampled, repeating; red and green are two
    // independent layers with values in [0, 1] and mean 0.5). Without it the plugin makes its own.
    std::optional<ImageInput> noise;
    double timeSeconds = 0.0;  // scrolls the noise; any finite value
    // For an engine that keeps its HDR color pre-exposed (multiplied by an exposure factor k, as
    // Unreal's and Filament's pre-exposure do): the composite becomes color * exp(-betaT S) + k
    // Lin. inscatterOut receives Lin unexposed. In [0, limits::kMaxPreExposure].
    float preExposure = 1.0f;
    // Optional: the scene's occluders for seed 004's methods (at most kMaxOccluders; each checked:
    // finite, orthonormal axes, positive extents, the inner box inside the outer one). Checked
    // only when the frame's method reads them (beam-tree-*, or auto when it picks one); the other
    // methods ignore them, however many there are.
    std::vector<Occluder> occluders;
    Camera camera;
    // One light, with `shadowMap` and `lightColor` above. The plugin takes it as the list of that
    // one light (lights = {light}, its id 0) at its edge, and nothing after that point tells the
    // two apart: the same light given either way renders the same image and report. Only the
    // names in refusals differ (light.field, not lights[0].light.field).
    Light light;
    // Several lights: when not empty, these replace `light`, `shadowMap` and `lightColor` (which
    // must then be left at their defaults; a frame giving both is refused naming the fields).
    // Inside the plugin they are ordered by LightInput::id. Each light gets its own chain of nodes
    // writing its own Lin (a one-per-frame method, MethodInfo::onePerFrame, injects them all into
    // one chain); the extinction is applied once and the Lins are added: color = color *
    // exp(-betaT S) + sum of Lin (inscatterOut receives the sum). A light whose volume misses the
    // view adds no node. Errors name lights[i].field, i the light's position in this list. Every
    // method takes a list; a method that cannot honour one of its lights refuses the frame naming
    // lights[i]. At most kMaxLights.
    std::vector<LightInput> lights;
    Medium medium;
    // The method of every light whose LightInput::method is Auto; Auto chooses for each light.
    Method method = Method::Epipolar;
    Profile profile = Profile::Balanced;
    // The engine's settings. With Profile::Custom all of them; with any other profile all but the
    // fields the profile decides (SettingsField::profileSized: epipolar.slices and
    // samplesPerSlice, shadowMapSize, planes.count and planes.target), which the
    // profile decides. A light's own LightInput::settings replace them for its chain.
    Settings custom;
    DebugOptions debug;
    // A camera cut: the frame ignores what earlier frames left (froxels' temporal history,
    // Settings::froxels.temporal), renders as a new plugin's first frame would, and starts the
    // history anew. Only a method that keeps history reads it.
    bool resetHistory = false;
};

// How to read FrameDescription::volumeOut. Column x covers the screen's pixels [x tile, (x + 1)
// tile) across (rows alike, row 0 at the top); the slices cut the view axis geometrically, slice k
// spanning camera-space z (the distance along the view axis, metres) in
//     [nearZ (farZ / nearZ)^(k / depth), nearZ (farZ / nearZ)^((k + 1) / depth)),
// and texel k holds the integral from the camera to that slice's far end. For a point at pixel
// position (px, py) (continuous: a pixel's centre is at + 0.5) and camera-space z:
//     u = depth ln(z / nearZ) / ln(farZ / nearZ), clamped to [0, depth]
//     g = the image sampled with a linear filter, clamped to its edge, at the normalised
//         (px / (width tile), py / (height tile), (max(u, 1) - 0.5) / depth)
//     within the first slice (u < 1): g = mix((0, 0, 0, 1), g, min(z / z1, 1)), z1 its far end
//     fogged = color g.a + g.rgb (times FrameDescription::preExposure for a pre-exposed color).
// That is how the plugin applies the grid to the depth buffer's pixels. nearZ is the camera's near
// plane; farZ the smallest of Settings::froxels.farDistance (when not 0), medium.maxDistance and a
// finite far plane. Beyond farZ the last slice holds.
struct FroxelVolume {
    uint32_t width = 0, height = 0, depth = 0;  // volumeOut's extent: columns, rows, slices
    uint32_t tile = 0;                          // pixels per column, across and down
    float nearZ = 0.0f, farZ = 0.0f;
};
// The froxel grid a frame would build (its first light reaching the view decides the settings,
// its own or the frame's), for a screen of depth.extent, or of `maxRenderSize` when the plugin was
// created with one. Throws InvalidInput as Plugin::check() does for the frame's fields; the image
// handles are not looked at, so an engine may call it before it makes volumeOut.
LIGHTSCATTER_API FroxelVolume froxelVolume(const FrameDescription& frame,
                                           VkExtent2D maxRenderSize = {0, 0});

// Thrown before anything is recorded when a description breaks a rule; the message, one line, names
// the field (as a path from FrameDescription: "custom.epipolar.slices", "depth.layout"; or from
// VulkanContext: "context.enabledFeatures"), both fields for a rule between two, and the rule. An
// enum holding a value that is none of its enumerators (a cast integer) is refused so too, at every
// entry point that takes one. The engine's images and command buffer are untouched.
class LIGHTSCATTER_API InvalidInput : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

// Thrown when Vulkan fails the plugin: out of device or host memory while building a frame's
// textures or pipelines, a lost device. The message names the call, and the resource or pass.
class LIGHTSCATTER_API DeviceError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

struct PassTime {
    std::string name;
    double milliseconds = 0;
    // The samples an epipolar ray march marched (the first march, and with
    // Settings::epipolar.inscatterRefinementThreshold the refinement's, which marches only the
    // samples it adds), counted by an occlusion query; -1 for the other passes.
    int64_t samples = -1;
};

// What epipolar's ray march did in a frame (DebugOptions::countSteps), summed over the frame's
// lights. The fix-up's per-pixel marches are not counted. Divide by `samples` for a per-sample
// cost; counts do not depend on the device or its load.
struct StepCounts {
    uint64_t samples = 0;    // ray-marching samples marched (once each, whatever the cube faces)
    uint64_t rays = 0;       // of them, rays that cross the shadow map's frustum (per cube face)
    uint64_t lineSteps = 0;  // level-0 steps along the slices' lines: a shadow-map look-up each
    uint64_t treeNodes = 0;  // min/max tree nodes tested (0 without trees)
    // Rays off their slice's line (along the light's direction, or against the line), marched on
    // their own one texel at a time, and their shadow-map look-ups.
    uint64_t degenerateRays = 0;
    uint64_t degenerateSteps = 0;
    // Of the samples, those the first march took from the list of refined samples it compacts
    // (epipolar: docs/epipolar.md, "The march list"); 0 where a frame's refinement overflowed it.
    uint64_t listedSamples = 0;
    // Of the tree nodes tested, those before where the trees pass began their slice's tree (the
    // part of a line no ray of the slice can reach, skipped: docs/epipolar.md, "Trees from the
    // camera on"). Always 0; counted so that tests can show it.
    uint64_t unbuiltTreeNodes = 0;
};

struct FrameReport {
    uint64_t frame = 0;             // the frame this report covers (record()'s number; 0: none yet)
    std::string method;             // the method that ran; with Auto, the one it picked
    std::string reason;             // which nodes the frame needed, and with Auto why that method
    std::string notice;             // empty, or one line: an assumption of the method this frame's
                                    // medium or light breaks, and what it costs
    bool timed = false;             // false: that frame has not finished on the GPU (passes empty)
    std::vector<PassTime> passes;   // GPU time per pass, execution order
    std::vector<PassTime> cpuWork;  // CPU time the plugin spent preparing the frame (the beam tree)
    double totalMilliseconds = 0;
    std::string device;
    // The nodes this frame was built from. With several lights a node's name ends in "(light N)",
    // N its light's place in the plugin's order (by LightInput::id), not in the engine's list: a
    // reordered list reuses the graph, names included.
    std::vector<std::string> passNames;
    // Passes of the frame that fill what the plugin keeps across frames, this time (the point-light
    // table: its first frame, or a new medium; the tiling noise: its first frame).
    std::vector<std::string> setupPasses;
    // This frame compiled a frame graph: its configuration (sizes, formats, layouts, the method,
    // the lights' kinds and settings, in the order of their ids) was met for the first time, or not
    // among the graphs kept (the plugin keeps the last 8 it used). Other frames reuse a compiled
    // graph: the same lights with ids in another order among them.
    bool graphCompiled = false;
    std::string depthStencilFormat;  // what was chosen for the stencil textures
    // With DebugOptions::countSteps on an epipolar frame, once `timed` (the frame is done): what
    // its ray march did. Empty otherwise.
    std::optional<StepCounts> steps;
    // One entry per light, in the order the engine gave them (FrameDescription::lights, not the
    // ids' order): the method its chain ran ("none" for a light that reaches no view ray), why
    // (with Auto, why that method), and the notice of its method.
    struct Light {
        std::string method;
        std::string reason;
        std::string notice;
        // The settings its chain ran with: the profile's sizes over the frame's `custom` (or the
        // light's own LightInput::settings), as checked. A tool can show what a frame really used.
        Settings settings;
    };
    std::vector<Light> lights;
};

// Memory of one resource of the method, as the budget reports it.
struct BudgetEntry {
    std::string name;
    std::string format;
    uint32_t width = 0, height = 0;
    uint64_t bytes = 0;
    bool transient = true;  // false: owned by the plugin across frames (look-up table)
    uint32_t depth = 1;     // a 3D texture's slices (froxels' grids)
};

struct Budget {
    Profile profile = Profile::Balanced;
    Settings settings;
    uint32_t screenWidth = 0, screenHeight = 0;
    std::vector<BudgetEntry> entries;
    uint64_t totalBytes = 0;  // everything, each in memory of its own
    uint64_t peakBytes = 0;   // with transient aliasing (plus persistent resources)
    bool estimated = true;    // sizes estimated without a device
    std::string depthStencilFormat;
    std::optional<SeedFigure> seed;         // the seed's published figure for this profile
    std::vector<std::string> lightMethods;  // the method of each light, in the list's order
};

// One light of a budgeted frame: its type, whether it has a shadow map (budget()'s shadowMapSize;
// a point light's a cube of six such faces where its method samples one), and its method. Auto
// picks as a frame's Auto does for a light that covers the screen in a medium that needs the
// point-light table: epipolar for a shadowed light (brute force on a screen too small for it), the
// closed form per pixel without a shadow map.
struct BudgetLight {
    LightType type = LightType::Spot;
    bool shadowed = true;
    Method method = Method::Auto;
};

// The memory of a frame of these lights for a profile, screen and shadow-map size, as a frame with
// that profile and `custom` (null: the defaults) builds it; needs no GPU. The transients of the
// lights' chains alias each other (the chains run one after the other); each point or spot light
// whose method reads one adds its own point-light table. Refused (InvalidInput) where a frame
// would be: a light its method cannot honour names lights[i]. Budget::lightMethods says the
// method each light got. Seed 000's figures (Budget::seed) come with a frame of one light.
// `colorFormat`: the engine's color (FrameDescription::color), a storage image where it is
// R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT, else an attachment, which adds the split
// composite's two screen textures.
LIGHTSCATTER_API Budget budget(
    Profile profile, uint32_t screenWidth, uint32_t screenHeight, uint32_t shadowMapSize,
    const std::vector<BudgetLight>& lights = {BudgetLight{LightType::Spot, true, Method::Epipolar}},
    const Settings* custom = nullptr, VkFormat colorFormat = VK_FORMAT_R16G16B16A16_SFLOAT);

// The device extensions the plugin needs; add them to VkDeviceCreateInfo::ppEnabledExtensionNames.
LIGHTSCATTER_API std::vector<const char*> requiredDeviceExtensions();

// The device features the plugin needs, as a chain for VkDeviceCreateInfo::pNext:
//     lightscatter::DeviceFeatures features = lightscatter::requiredDeviceFeatures();
//     features.vulkan12.timelineSemaphore = VK_TRUE;   // the engine's own, if any
//     createInfo.pNext = features.chain();             // after the last copy or move
//     ... vkCreateDevice(...); context.enabledFeatures = features.chain();
// chain() links core -> vulkan11 -> vulkan12 -> vulkan13 and leaves vulkan13.pNext as it is (the
// engine may hang its extension structures there).
struct DeviceFeatures {
    DeviceFeatures() {
        core.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
        vulkan11.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES;
        vulkan12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
        vulkan13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
        chain();
    }
    VkPhysicalDeviceFeatures2* chain() {
        core.pNext = &vulkan11;
        vulkan11.pNext = &vulkan12;
        vulkan12.pNext = &vulkan13;
        return &core;
    }
    VkPhysicalDeviceFeatures2 core{};
    VkPhysicalDeviceVulkan11Features vulkan11{};
    VkPhysicalDeviceVulkan12Features vulkan12{};
    VkPhysicalDeviceVulkan13Features vulkan13{};
};
LIGHTSCATTER_API DeviceFeatures requiredDeviceFeatures();
// The same, with the optional features `physical` has turned on as well: dualSrcBlend (a
// composite path that blends with two sources, taken where the device enabled it; the plugin never
// requires it). Asks `physical` with vkGetPhysicalDeviceFeatures (Vulkan 1.0, of any instance)
// through `getInstanceProcAddr` (null: the loader's, as PluginCreateInfo::getInstanceProcAddr);
// throws DeviceError where there is no loader.
LIGHTSCATTER_API DeviceFeatures
requiredDeviceFeatures(VkInstance instance, VkPhysicalDevice physical,
                       PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr);

// For an engine with a feature chain of its own: turns on, in that chain, every feature the plugin
// needs and leaves the rest as it is. The chain must hold a structure for each
// (Vulkan12/13Features, or the feature's own structure such as
// VkPhysicalDeviceMaintenance4Features); throws InvalidInput naming the structure that is missing,
// changing nothing.
LIGHTSCATTER_API void enableRequiredDeviceFeatures(VkPhysicalDeviceFeatures2& features);

// For an engine whose device creation takes the core features and the pNext chain apart (a
// framework that is given a VkPhysicalDeviceFeatures and a pNext, and builds a
// VkPhysicalDeviceFeatures2 of its own inside device creation): turns on, field by field, the
// plugin's features in `core` and in the structures `pNext` chains, as enableRequiredDeviceFeatures
// does, and leaves every other field, sType and pNext as it is. Throws InvalidInput naming each
// structure the chain lacks (the plugin needs Vulkan 1.2's and 1.3's features: their versioned
// structures, or each feature's own), changing nothing. Tell the plugin what was enabled all the
// same (VulkanContext::enabledFeatures: a VkPhysicalDeviceFeatures2 of the engine's holding
// `core`, its pNext `pNext`):
//     lightscatter::mergeRequiredDeviceFeatures(enabledFeatures, &features12, instance, physical);
//     ... createLogicalDevice(enabledFeatures, extensions, &features12);
//     VkPhysicalDeviceFeatures2 enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
//     enabled.features = enabledFeatures;
//     enabled.pNext = &features12;  // the same chain, features12 -> features13 -> ...
//     context.enabledFeatures = &enabled;  // read by the Plugin constructor, not kept
LIGHTSCATTER_API void mergeRequiredDeviceFeatures(VkPhysicalDeviceFeatures& core, void* pNext);
// The same, with the optional features `physical` has (requiredDeviceFeatures(instance, physical,
// getInstanceProcAddr)) turned on in `core` too.
LIGHTSCATTER_API void mergeRequiredDeviceFeatures(
    VkPhysicalDeviceFeatures& core, void* pNext, VkInstance instance, VkPhysicalDevice physical,
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr);

// What `physical` lacks of what the plugin requires, for an engine that picks a physical device
// before it makes a device of it: one entry per lack, in this order, empty when it lacks nothing.
//     "VkApplicationInfo::apiVersion 1.3 or later (the instance's is 1.0.0)"
//     "Vulkan 1.3 (the device offers 1.2.189)"
//     each extension of requiredDeviceExtensions() it does not offer, by name
//     each feature requiredDeviceFeatures() turns on that it does not have, by its field's name
//     "a queue family with graphics, compute and timestamps"
// `instanceApiVersion` is the VkApplicationInfo::apiVersion `instance` was created with (Vulkan
// cannot be asked for it; 0 is 1.0). Below 1.3 on either side only Vulkan 1.0 calls are made, so
// the 1.1 to 1.3 features are neither asked for nor listed: the version's entry says what they
// wait on. Optional features (dualSrcBlend) are never listed. Entry points come from
// `getInstanceProcAddr` (null: the loader's); throws DeviceError where there is no loader.
LIGHTSCATTER_API std::vector<std::string> missingDeviceFeatures(
    VkInstance instance, VkPhysicalDevice physical, uint32_t instanceApiVersion,
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr);

// The engine's Vulkan objects the plugin works with. The plugin never destroys them.
struct VulkanContext {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;  // of `queue`; needs graphics, compute and timestamps
    // Required: the feature chain the engine gave vkCreateDevice (VkDeviceCreateInfo::pNext), which
    // Vulkan cannot be asked for afterwards. The Plugin constructor reads it (and keeps nothing)
    // and refuses, with InvalidInput naming them, features the plugin needs that are not enabled.
    // An engine that gave VkDeviceCreateInfo::pEnabledFeatures, or whose framework built the
    // VkPhysicalDeviceFeatures2 and let it go, gives one of its own with the same features and
    // chain (mergeRequiredDeviceFeatures shows how). Optional features (dualSrcBlend) are used
    // where this chain turns them on.
    const VkPhysicalDeviceFeatures2* enabledFeatures = nullptr;
    // Required: the VkApplicationInfo::apiVersion the engine created `instance` with, which Vulkan
    // cannot be asked for: VK_API_VERSION_1_3 or later, as the plugin calls Vulkan 1.3 (an instance
    // created for 1.0 gives none of 1.1's to 1.3's entry points, whatever the device offers). The
    // Plugin constructor refuses a lower version with InvalidInput naming context.apiVersion and
    // the version found, before any Vulkan call; 0, the default, is refused the same way (it is
    // both "not given" and what Vulkan reads as 1.0). The physical device must offer 1.3 too
    // (VkPhysicalDeviceProperties::apiVersion, asked with Vulkan 1.0's call): refused naming
    // context.physicalDevice and its version, before any Vulkan 1.1 call.
    uint32_t apiVersion = 0;
};

// The most frames an engine may have in flight (PluginCreateInfo::framesInFlight).
inline constexpr uint32_t kMaxFramesInFlight = 8;

// How a Plugin is made. (The context comes second, so that a braced list of a VulkanContext's
// handles still means a VulkanContext.)
struct PluginCreateInfo {
    // The engine's frames in flight, 1 to kMaxFramesInFlight: when it records frame N (record()'s
    // N-th call), the frame it recorded framesInFlight calls before (N - framesInFlight) has
    // completed on the GPU, as the usual fence per frame slot makes sure. The plugin destroys
    // what only completed frames used then, and never waits for the GPU itself.
    uint32_t framesInFlight = 2;
    VulkanContext context;
    // Where the plugin's Vulkan entry points come from: the engine's vkGetInstanceProcAddr (volk's,
    // a layer's, one that counts or traces calls), through which the plugin asks
    // vkGetDeviceProcAddr for the device's own. Null: the Vulkan loader's, from libvulkan.so.1
    // opened at run time. The library binds no vk* symbol either way.
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
    // The host allocator every Vulkan object of the plugin is created and destroyed with (null:
    // the driver's). Device memory is Vulkan's to allocate as always.
    const VkAllocationCallbacks* allocator = nullptr;
    // Dynamic resolution (as FidelityFX's maxRenderSize): zero, none. Otherwise the plugin builds
    // its graphs for this size, and each frame's engine images (depth, color, inscatterOut) may be
    // any size within it, changing every frame without building anything; a frame larger than it
    // is refused (InvalidInput naming depth.extent). The textures are this size's whatever the
    // frame's. The engine's images may be larger than the frame (ImageInput::extent is the frame's,
    // its top-left rectangle): no pass reads or writes them outside it. A frame within the maximum
    // renders what a plugin without one renders at its size, bit for bit, but for froxels: their
    // grid has the maximum's columns (froxelVolume()), sampled at coordinates that differ from a
    // grid of the frame's size in their last bits, and so does the image (about 1e-7 relative).
    // Without it, a frame of a new size builds (once) a graph for that size, while the old size's
    // graph stays kept for when the size comes back.
    VkExtent2D maxRenderSize{0, 0};
};

// The header's version as a type (Plugin's constructor): a library of another version lacks the
// constructor that takes it, and the engine fails to link rather than to run.
#define LIGHTSCATTER_VERSION_TAG_NAME(major, minor) HeaderVersion_##major##_##minor
#define LIGHTSCATTER_VERSION_TAG(major, minor) LIGHTSCATTER_VERSION_TAG_NAME(major, minor)
struct LIGHTSCATTER_VERSION_TAG(LIGHTSCATTER_VERSION_MAJOR, LIGHTSCATTER_VERSION_MINOR) {};

// The plugin in an engine's frame loop: what it promises, and what it asks of the engine.
//
// Threads. One Plugin is used by one thread at a time (its calls are not synchronised). Plugins
// may be used on several threads at once, on one VkDevice or several: they share their device's
// pipelines and samplers, which are synchronised. record() touches no VkQueue. render() submits
// to VulkanContext::queue and waits on a fence of its own: no other thread may use that queue
// meanwhile (Vulkan's rule). The free functions (budget(), the names, requiredDevice*()) are safe
// from any thread.
//
// Frames in flight and recording ahead. record() never waits for the GPU and never submits:
// everything a frame needs is recorded into the engine's command buffer, and what the plugin
// creates (pipelines, memory, views) is created on the host. The engine submits the command
// buffers it recorded into, each one, in the order it recorded them, on one queue (or queues it
// orders that way): a frame may fill what later frames read (the point-light table) and shares
// memory with the frames around it. It may record any number of frames ahead of their
// submission, up to framesInFlight: recording frame N promises that frame N - framesInFlight has
// completed. Each frame renders with its own description (medium, lights, matrices, time), however
// far ahead it was recorded. Configurations met before (a size, a method, a light leaving and
// coming back) reuse the graph compiled for them: the plugin keeps the last 8.
//
// Images. The engine's images are read or written only by the commands record() put in its
// command buffer; the plugin keeps no handle of them after record() returns (it makes views of
// them for each frame and destroys those after the frame has completed), so an image may be
// destroyed once the frames that used it have completed, and a new image that gets the old one's
// handle is a new image to the plugin. Each image is left in the layout, stages and access its
// ImageInput's final* fields ask for.
//
// The command buffer after record(): still recording, primary (secondary command buffers are not
// supported), outside any render pass or dynamic rendering scope, as it was given. What record()
// bound or set is left as it set it: pipelines, push constants and push descriptors of both
// bind points, viewport, scissor and stencil reference. The engine binds its own state again.
//
// Destruction. ~Plugin waits for nothing: destroy the plugin after every frame it recorded has
// completed on the GPU (the engine's fences, or vkDeviceWaitIdle at shutdown), and before the
// VkDevice. render()'s frames have completed when it returns.
//
// A lost device. A Vulkan call that reports VK_ERROR_DEVICE_LOST (render()'s fence, report()'s
// queries) throws DeviceError naming the call. The plugin is then good only for destruction, which
// calls nothing that can fail: destroy it, then the device, and make both again.
class LIGHTSCATTER_API Plugin {
  public:
    using HeaderVersion = LIGHTSCATTER_VERSION_TAG(LIGHTSCATTER_VERSION_MAJOR,
                                                   LIGHTSCATTER_VERSION_MINOR);
    // Throws InvalidInput for a context that lacks a handle, the Vulkan version or a feature (see
    // VulkanContext), or framesInFlight out of its range.
    explicit Plugin(const PluginCreateInfo& info) : Plugin(info, HeaderVersion{}) {}
    // PluginCreateInfo{2, context}: two frames in flight.
    explicit Plugin(const VulkanContext& context);
    // Waits for nothing (see "Destruction" above).
    ~Plugin();
    Plugin(const Plugin&) = delete;
    Plugin& operator=(const Plugin&) = delete;

    // Validates the description (throws InvalidInput, nothing recorded), builds or reuses the
    // frame's graph, and records it into `cmd`, which must be a primary command buffer in the
    // recording state, outside any render pass. Returns the frame's number (1, 2, ...), which
    // report() takes once the engine's fence says the frame is done. Never waits, never submits.
    //
    // Exception guarantee (record and render): if InvalidInput or DeviceError is thrown, nothing
    // has been recorded into `cmd`, the engine's images are untouched, no Vulkan object is leaked,
    // and the plugin is usable: a graph that failed to build is dropped and built again by the next
    // call, which succeeds once memory is available again. Everything a frame creates (textures,
    // pipelines) is created, and can fail, before `cmd` is touched. std::bad_alloc (the host out
    // of memory) gives the same guarantee while the frame is being built; thrown while commands are
    // being recorded (their barriers and descriptor writes take host memory), `cmd` may hold part
    // of the frame: reset it or drop it. No test makes the host run out of memory.
    uint64_t record(VkCommandBuffer cmd, const FrameDescription& frame);
    // Validates, records into the plugin's own command buffer, submits, waits, reports.
    FrameReport render(const FrameDescription& frame);
    // Validates the description as record() does, and whether its method can honour it, throwing
    // the same InvalidInput; records, builds and changes nothing. For a tool that checks many
    // configurations before the first frame (the host's benchmark does).
    void check(const FrameDescription& frame) const;
    // The GPU times of a frame, read without waiting: `timed` is false while the GPU has not
    // finished it (or it was never submitted). The plugin keeps the times of the last kTimedFrames
    // frames, whatever graph each was recorded with; an older frame throws InvalidInput. Each
    // frame keeps its own queries, so frames may be recorded ahead of their submission.
    static constexpr uint64_t kTimedFrames = 8;
    FrameReport report(uint64_t frame);
    // The last frame recorded (or rendered); frame 0 and nothing else before the first.
    FrameReport report();

    // The compiled frame graph, for tools.
    std::string graphDot() const;
    std::string graphJson() const;

  private:
    Plugin(const PluginCreateInfo& info, HeaderVersion);
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace lightscatter
