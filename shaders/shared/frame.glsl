// Per-frame constants (mirrors passes/shared/frame_constants.h, std140) and the specialisation
// constants that select the light, the phase function and the options: the plugin compiles one
// pipeline per combination instead of branching per pixel.
#ifndef LS_FRAME_GLSL
#define LS_FRAME_GLSL

layout(constant_id = 0) const int kLightType = 0;       // 0 directional, 1 spot, 2 point
layout(constant_id = 1) const int kMiePhase = 0;        // 0 Cornette-Shanks, 1 isotropic, 2 hazy
layout(constant_id = 3) const bool kLightColor = false;  // colored shafts from a light-space texture
layout(constant_id = 4) const bool kBilinearShadow = true;
// Seed 004's simplified light model (Settings::lightModel, eqs. 2.12-2.17): irradiance
// I / (a1 r^2 + a0), no transmittance, isotropic phase; the shaders that honour it read
// frame.simplified (simplified.glsl, light_at.glsl).
layout(constant_id = 5) const bool kSimplifiedModel = false;

const int LIGHT_DIRECTIONAL = 0;
const int LIGHT_SPOT = 1;
const int LIGHT_POINT = 2;
const float PI = 3.14159265358979;

layout(std140, set = 0, binding = 0) uniform FrameConstants {
    mat4 viewProj;       // world -> camera clip
    // The ray through NDC (x, y) points along x col0 + y col1 + col2 (xyz, unnormalised; col2 is
    // the unit view axis): made from the projection's rows in double precision, never from a
    // point unprojected near the camera minus the camera's position, which cancels when the
    // near plane is small (passes/shared/scattering_params.cpp).
    mat4 rayBasis;
    mat4 lightViewProj;  // world -> light clip (the shadow map)
    vec4 cameraPos;      // xyz; w: near
    vec4 cameraForward;  // xyz: unit view axis; w: far (ignored when infinite)
    vec4 screenSize;     // w, h, 1/w, 1/h
    vec4 lightPos;       // xyz (point, spot)
    vec4 lightDir;       // xyz: direction light travels / spot axis; w: cos(half angle)
    vec4 lightIntensity; // rgb: E (directional) or I; w: spot range
    vec4 lightScreen;    // xy: NDC of the light (or of the point the shafts converge to); z: sign of
                         // its clip w (+1 in front of the camera, -1 behind); w: 1 when on screen
    vec4 betaR;          // rgb; w: g
    vec4 betaM;          // rgb; w: max distance (sky)
    vec4 betaT;          // rgb; w: r0
    vec4 depthInfo;      // x: reversed z, y: infinite far, z: near, w: far
    vec4 shadowInfo;     // x: shadow-map size, y: 1/size, z: reversed z, w: depth bias
    vec4 epipolar;       // x: slices, y: samples per slice, z: initial step, w: refinement threshold
    vec4 epipolar2;      // x: bilateral threshold, y: fix-up max steps (0: all), z: tree levels,
                         // w: 1 when samples carry the shadowed fraction instead of Lin
    vec4 lutInfo;        // x: log range of hEff / r0, y: table width, z: table height, w: -
    vec4 simplified;     // kSimplifiedModel: x: a0 / a1 (at least 1e-12), y: 1 / a1, zw: -
    vec4 cubeFace;       // x: the cube face (layer) an epipolar per-face pass marches, in the
                         // order below (lightViewProj is then that face's matrix); y: 1 when the
                         // face's frustum reaches the view (always 1 outside per-face passes)
    vec4 epipolar3;      // x: in-scattering refinement threshold (0: off), yzw: -
    vec4 linStorage;     // x: the power of two Lin is stored with between a method's passes and
                         // the composite (float16 targets hold at most 65504), y: 1 / x
    // A point light's cube shadow map (LS_CUBE_SHADOW): world -> clip of each face, in Vulkan's
    // face order +X, -X, +Y, -Y, +Z, -Z (the layers of the shadow map).
    mat4 cubeFaceViewProj[6];
} frame;

// Lin as a method leaves it for the composite and as the composite reads it back: scaled by the
// frame's power of two (plugin_api/lin_storage.h), which keeps the frame's brightest Lin within
// float16's range, and clamped to that range (a sampled method's peak may overshoot the bound).
// Exact: a power of two changes no float16 digit.
vec3 storedLin(vec3 lin) { return clamp(lin * frame.linStorage.x, vec3(-65504.0), vec3(65504.0)); }
vec3 loadedLin(vec3 stored) { return stored * frame.linStorage.y; }

#endif
