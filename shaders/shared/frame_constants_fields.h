// The fields of FrameConstants, written once for both languages: frame.glsl declares its std140
// uniform block with them, passes/shared/frame_constants.h its C++ struct (glm), each defining
// LS_MAT4, LS_VEC4 and LS_DEFAULT (a C++ default member value; nothing in GLSL) before including
// this. Only mat4 and vec4 members, in this order: std140 then places every member where the C++
// struct does, and frame_constants.h checks the size of the whole.
LS_MAT4 viewProj;  // world -> camera clip
// World offsets from the camera -> camera clip (the projection times the view's rotation): a pass
// that rasterises geometry it places around the camera (planes) adds no world translation that
// cancels in float far from the origin (at 1e6 m, steps of 6 cm).
LS_MAT4 viewProjFromCamera;
// The ray through NDC (x, y) points along x col0 + y col1 + col2 (xyz, unnormalised; col2 is
// the unit view axis): made from the projection's rows in double precision, never from a
// point unprojected near the camera minus the camera's position, which cancels when the
// near plane is small (passes/shared/scattering_params.cpp).
LS_MAT4 rayBasis;
LS_MAT4 lightViewProj;   // world -> light clip (the shadow map)
LS_VEC4 cameraPos;       // xyz; w: near
LS_VEC4 cameraForward;   // xyz: unit view axis; w: far (ignored when infinite)
LS_VEC4 screenSize;      // w, h, 1/w, 1/h
LS_VEC4 lightPos;        // xyz (point, spot)
LS_VEC4 lightDir;        // xyz: direction light travels / spot axis; w: cos(half angle)
LS_VEC4 lightIntensity;  // rgb: E (directional) or I; w: range (point, spot)
// x: cos of a spot's inner cone angle; y: 1 / (cos inner - cos outer), 0 for a hard edge; z: 1 when
// the range ends in KHR's window (else it cuts); w: the penumbra's angle, outer - inner (radians)
LS_VEC4 lightFalloff;
LS_VEC4 lightScreen;  // xy: NDC of the light (or of the point the shafts converge to); z: sign of
                      // its clip w (+1 in front of the camera, -1 behind); w: 1 when on screen
LS_VEC4 betaR;        // rgb; w: g
LS_VEC4 betaM;        // rgb; w: max distance (sky)
LS_VEC4 betaT;        // rgb; w: r0
LS_VEC4 depthInfo;    // x: reversed z, y: infinite far, z: near, w: far
LS_VEC4 shadowInfo;   // x: shadow-map size, y: 1/size, z: reversed z, w: depth bias
LS_VEC4 lutInfo;      // x: log range of hEff / r0, y: table width, z: table height, w: -
LS_VEC4 simplified;   // kSimplifiedModel: x: a0 / a1 (at least 1e-12), y: 1 / a1, zw: -
// x: the power of two Lin is stored with between a method's passes and the composite (float16
// targets hold at most 65504), y: 1 / x, z: the engine's pre-exposure (the composite adds z Lin)
LS_VEC4 linStorage LS_DEFAULT(1.0f, 1.0f, 1.0f, 0.0f);
// xy: the size of the screen-sized textures (the plugin's maxRenderSize, or the screen), zw: the
// screen's share of them (screenSize.xy / xy; 1 without a maximum)
LS_VEC4 screenTexels LS_DEFAULT(1.0f, 1.0f, 1.0f, 1.0f);
// A point light's cube shadow map (LS_CUBE_SHADOW): world -> clip of each face, in Vulkan's
// face order +X, -X, +Y, -Y, +Z, -Z (the layers of the shadow map).
LS_MAT4 cubeFaceViewProj[6];
// A non-uniform medium (medium.glsl; read only where kMedia != 0): x: the whole-scene density d0,
// y: the height fog's base height, z: its falloff (0 without height fog), w: the number of fog
// volumes below (those that can touch the view or the light's path to it).
LS_VEC4 medium;
// x: the length over which a non-uniform medium's integrand changes little (the height fog's
// 1 / falloff, a volume's fade, a fifth of a mean free path at the densest point), the longest
// piece a point or spot light's integral takes (integrate.glsl); yzw: -
LS_VEC4 mediumScale;
// Each fog volume: rows 0-2 the box's local axes in world space (xyz) and -dot(axis, centre) (w),
// so that dot(row, vec4(x, 1)) is x's local coordinate; row 3: the half extents (xyz) and the
// fade (w). Stored as a mat4's columns.
LS_MAT4 fogVolumes[LS_MAX_FOG_VOLUMES];
LS_VEC4 fogDensity[LS_MAX_FOG_VOLUMES / 4];  // volume i's density: [i / 4][i % 4]
