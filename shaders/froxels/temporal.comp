#version 450
#extension GL_GOOGLE_include_directive : require
// The temporal mode's blend: each froxel's in-scattering, sampled this frame at its own jittered
// point, blended with the frame before's grid where that frame saw the froxel's centre (reprojected
// with its camera and its slices): lerp(this frame's, history, weight), with what engines do
// against ghosting. The history is fetched with a Catmull-Rom filter across columns and rows (a
// trilinear fetch blurs it a little more each frame the camera moves), then clamped to the range of
// this frame's samples in the 3x3x3 froxels around (each sampled at its own point, so the range
// spans what the froxel holds), so that a shaft that left a froxel takes its history with it. Where
// this frame's froxel knows its unshadowed in-scattering exactly (a point or spot light's slab: the
// injections' alpha), the history is first carried to it, so that the blend averages only the
// shadow and cookie. Where a light changed since the frame before (the host compares their
// constants), a history that lay further outside that range than the threshold is dropped: the
// light's contribution changed there, not the sampling. Where the history does not cover the froxel
// (off its frustum, or no history) or is dropped, the froxel keeps this frame's sample. The result
// is the grid the integration reads and the next frame's history; this frame's samples stay as they
// were, for the ranges of the froxels around. In the per-pixel history's still frames (blend.w) the
// samples lie on offset columns, which the apply gathers: the grid is kept as the last frame that
// moved left it, for the exported volume and for the next frame that moves (copied by the first
// such frame; the host records nothing for the later ones).
#define LS_FROXEL_TEMPORAL 1
#include "froxel_grid.glsl"
#include "froxel_bindings.h"
// A froxel per invocation, 32 x 4 of one slice a group: rows of neighbours in a warp on a GPU, and
// on lavapipe half the time of 4 x 4 x 4 groups (its 8-wide vectors run along x).
layout(local_size_x = 32, local_size_y = 4, local_size_z = 1) in;
layout(binding = LS_BINDING_FROXEL_SCATTERING, rgba32f) uniform readonly image3D scattering;
// Read as storage (GENERAL), so that the plugin's images rest in SHADER_READ_ONLY_OPTIMAL between
// frames and a graph's first frame, which finds them UNDEFINED, has a barrier to give them a layout.
layout(binding = LS_BINDING_FROXEL_HISTORY, rgba32f) uniform readonly image3D history;
layout(binding = LS_BINDING_FROXEL_HISTORY_OUT, rgba32f) uniform writeonly image3D historyOut;

// Catmull-Rom's weights of the four texels around a point f of the way from the second to the
// third.
vec4 catmullRom(float f) {
    return vec4(f * (-0.5 + f * (1.0 - 0.5 * f)), 1.0 + f * f * (-2.5 + 1.5 * f),
                f * (0.5 + f * (2.0 - 1.5 * f)), f * f * (-0.5 + 0.5 * f));
}

// The history at texture coordinates t: Catmull-Rom across the columns and rows, linear along
// the slices (clamped to its edge froxels). Its negative lobes may undershoot; the range clamp
// bounds it. Alpha: its unshadowed in-scattering, -1 where a tap's is unknown.
vec4 historyAt(vec3 t) {
    ivec3 g = ivec3(pc.grid.xyz);
    vec3 p = t * pc.grid.xyz - 0.5;
    ivec3 i0 = ivec3(floor(p));
    vec3 f = p - vec3(i0);
    vec4 wx = catmullRom(f.x), wy = catmullRom(f.y);
    vec4 r = vec4(0.0);
    bool point = false;  // a tap's unshadowed value is a point sample's (its alpha -1)
    for (int k = 0; k < 2; ++k)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                ivec3 q = clamp(i0 + ivec3(x - 1, y - 1, k), ivec3(0), g - 1);
                vec4 h = imageLoad(history, q);
                point = point || h.a < 0.0;
                r += wx[x] * wy[y] * (k == 0 ? 1.0 - f.z : f.z) * h;
            }
    if (point) r.a = -1.0;
    return r;
}

// Where the frame before's grid saw the centre of froxel f, as its texture coordinates; false
// where it did not (behind its near plane, off its frustum or past its far distance).
bool reprojected(ivec3 f, out vec3 t) {
    vec3 v = rayDirection(columnNdc(vec2(f.xy), vec2(0.5)));
    vec3 P = frame.cameraPos.xyz + v * (sliceZ(float(f.z) + 0.5) / axisCosine(v));
    // The frame before's clip w is its camera-space z (Vulkan's perspective: w = -z_view).
    vec4 X = pc.previousViewProj * vec4(P, 1.0);
    t = vec3(0.0);
    if (X.w <= pc.previousSlices.x) return false;
    vec2 columns = (X.xy / X.w * 0.5 + 0.5) * frame.screenSize.xy / pc.grid.w;
    float u = log(X.w / pc.previousSlices.x) / pc.previousSlices.z * pc.grid.z;
    t = vec3(columns / pc.grid.xy, u / pc.grid.z);
    return all(greaterThanEqual(t, vec3(0.0))) && all(lessThanEqual(t, vec3(1.0)));
}

void main() {
    ivec3 f = ivec3(gl_GlobalInvocationID);
    ivec3 g = ivec3(pc.grid.xyz);
    if (any(greaterThanEqual(f, g))) return;
    if (pc.blend.w > 0.5) {
        imageStore(historyOut, f, imageLoad(history, f));
        return;
    }
    vec4 current = imageLoad(scattering, f);
    vec3 s = current.rgb;
    vec3 t;
    if (pc.previousSlices.w > 0.5 && reprojected(f, t)) {
        vec3 lo = s, hi = s;
        for (int k = 0; k < 27; ++k) {
            ivec3 q = clamp(f + ivec3(k % 3, (k / 3) % 3, k / 9) - 1, ivec3(0), g - 1);
            vec3 c = imageLoad(scattering, q).rgb;
            lo = min(lo, c);
            hi = max(hi, c);
        }
        vec4 history = historyAt(t);
        vec3 h = history.rgb;
        // A point or spot light's slab has its unshadowed in-scattering exact in each frame; what
        // the history averages is the shadow and cookie. So the history is carried to this
        // frame's unshadowed value, as the share of it that was lit: a moving light's glow leaves
        // no trail, and a froxel the light left is dark at once. Where the history held no light
        // and this frame's froxel has some, the history tells nothing of it.
        bool carried = current.a >= 0.0 && history.a >= 0.0;
        if (carried) h = history.a > 1e-30 ? h * (current.a / history.a) : s;
        vec3 clamped = clamp(h, lo, hi);
        // How far outside the range the history lay, in range widths (its farthest channel).
        vec3 outside = abs(h - clamped) / max(hi - lo, vec3(1e-30));
        bool dropped =
            pc.blend.y > 0.5 && max(outside.r, max(outside.g, outside.b)) > pc.blend.z;
        if (!dropped) s = mix(s, clamped, pc.blend.x);
    }
    imageStore(historyOut, f, vec4(s, current.a));
}
