#version 450
#extension GL_GOOGLE_include_directive : require
// The froxel grid applied per pixel: Lin and the transmittance from the camera to the pixel's
// camera-space z, by a trilinear fetch of the integrated grid, composited into the engine's color
// with the grid's transmittance (as engines do; docs/methods.md gives how far it is from
// exp(-betaT S)). Froxel k holds the integral to slice k + 1's start, so z at slice coordinate u
// reads the grid at depth (u - 0.5) / slices; within the first slice it blends from the camera's
// (0, 1).
// Beyond the far distance the grid's last froxel holds.
// The per-pixel history (LS_FROXEL_PIXEL_HISTORY): while nothing moves (the camera, the lights),
// the grid's columns step across a froxel from frame to frame (pc.shift), and each pixel gathers
// the Lin of the column nearest it, weighed by its distance to that column's ray, so that over the
// frames it collects rays that pass close to it: a reconstruction finer than a froxel, as TAA
// upsampling gathers a low-resolution frame's jittered samples. Gathered values stay near the range
// of the four columns around the pixel, so that a shaft that changed (an occluder moving in the
// light) leaves a bounded trail. A pixel holds what it gathered as detail: its difference from the
// fetch of the grid the temporal blend keeps. In a frame where something moved the grid stays put
// (its own blend follows the motion), and each pixel adds to this frame's trilinear fetch a fading
// share of the detail its surface had where the frame before saw it, so that the image does not
// jump from the gathered one to the grid's when a motion starts; after the first such frame the
// detail fades only as far as the fetch's own change hides (followFetch).
#define LS_FROXEL_APPLY 1
#include "froxel_grid.glsl"
#include "composite_into.glsl"
#include "froxel_bindings.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = LS_BINDING_DEPTH) uniform sampler2D depthBuffer;  // the engine's depth
layout(binding = LS_BINDING_FROXEL_INTEGRATED) uniform sampler3D integrated;
#if LS_FROXEL_PIXEL_HISTORY
// What a pixel gathered, as its difference from the kept grid's fetch (Lin, unscaled), and the
// weight it carries: the frame before's, and this frame's.
layout(binding = LS_BINDING_FROXEL_PIXELS, rgba32f) uniform readonly image2D pixels;
layout(binding = LS_BINDING_FROXEL_PIXELS_OUT, rgba32f) uniform writeonly image2D pixelsOut;
// The grid as the last frame that moved left it (the temporal blend keeps it in still frames),
// integrated: the pixels hold their detail against its fetch.
layout(binding = LS_BINDING_FROXEL_KEPT) uniform sampler3D kept;
#endif

// Pixel p's texture coordinates among the grid's columns offset by `shift` froxels (column c's ray
// at c + 0.5 + shift). Under dynamic resolution the grid has columns and rows beyond the frame's
// (`used` of them are the frame's): the frame's last half column reads its own last column alone,
// as the edge of a grid of the frame's size would (the clamp binds only then, so a grid of the
// frame's size reads what it always read).
vec2 columnCoordinates(ivec2 p, vec2 shift, vec2 used) {
    vec2 xy = (vec2(p) + 0.5 - shift * pc.grid.w) / (pc.grid.xy * pc.grid.w);
    return mix(xy, min(xy, (used - 0.5) / pc.grid.xy), lessThan(used, pc.grid.xy));
}

// An integrated grid's Lin (stored) and T at texture coordinates xyw, for a depth at slice
// coordinate u: the first slice starts at the camera (the integration's), linear in z from there
// (`first`, the depth's share of it).
vec4 gridAt(sampler3D grid, vec3 xyw, float u, float first) {
    vec4 g = textureLod(grid, xyw, 0.0);
    if (u < 1.0) g = mix(vec4(0.0, 0.0, 0.0, 1.0), g, first);
    return g;
}

#if LS_FROXEL_PIXEL_HISTORY
float meanOf(vec3 c) { return dot(c, vec3(1.0 / 3.0)); }

// A moving frame's detail: `faded` (what kPixelFade and the surface's motion leave of `detail`),
// limited so that what the pixel shows moves no further than its fetch moved since the frame
// before (`fetchBefore`, its mean over the channels there; each channel's change taken in
// proportion to it), less `driftShare` of the detail a frame (kDetailDrift; kMovingDetailDrift
// where the camera moved): the detail fades where the grid's own change hides it, and only that
// slowly elsewhere. The fade alone moves the image where the reference does not move: under a
// moving light on bench/froxels_flicker.json it flickered more than the plain grid in 3 of 8 cases
// (the atrium's sun at Unreal's size 1.72x), with this limit in none (docs/methods.md, "Still
// frames refined per pixel").
const float kDetailDrift = 0.005;
// Where the camera moved, the detail held goes stale as the scene slides under the columns: each
// pixel also gathers this frame's nearest column (weighed as a still frame weighs it) into what it
// showed, at a weight of kMovingMemory against the column's, and its detail drifts faster. On
// bench/froxels_flicker.json's camera motion point_fog's glow flickered 1.08x the plain grid's
// without them, 1.01x with them (a memory of 0.5, 1 or 4: 1.04x to 1.05x; gathered after the
// limit instead of before it: 1.07x; a drift of 0 or 1%: 1.03x to 1.05x; docs/methods.md).
const float kMovingMemory = 2.0;
const float kMovingDetailDrift = 0.02;
vec3 followFetch(vec3 detail, vec3 faded, vec3 fetch, float fetchBefore, float driftShare) {
    float m = meanOf(fetch);
    vec3 moved = (m - fetchBefore) * (m > 0.0 ? fetch / m : vec3(1.0));
    vec3 drift = driftShare * abs(detail);
    return detail + clamp(faded - detail, min(vec3(0.0), -2.0 * moved) - drift,
                          max(vec3(0.0), -2.0 * moved) + drift);
}
#endif

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    // The frame's extent, not the image's: under dynamic resolution the engine's images are larger
    // than the frame, and what lies outside it is the engine's.
    if (any(greaterThanEqual(p, ivec2(frame.screenSize.xy)))) return;
    float z = pixelCameraZ(depthBuffer, p);
    float u = clamp(sliceCoordinate(z), 0.0, pc.grid.z);
    // The grid's columns this frame, as texture coordinates.
    const vec2 used = ceil(frame.screenSize.xy / pc.grid.w);
    vec2 xy = columnCoordinates(p, pc.shift.xy, used);
    float w = (max(u, 1.0) - 0.5) / pc.grid.z;
    float first = u < 1.0 ? clamp(z / sliceZ(1.0), 0.0, 1.0) : 1.0;
    vec4 g = gridAt(integrated, vec3(xy, w), u, first);
    vec3 lin = max(g.rgb, vec3(0.0)) / pc.slices.w;
#if LS_FROXEL_PIXEL_HISTORY
    // This frame's column nearest the pixel, at its depth, and the range of the four around.
    vec2 cell = xy * pc.grid.xy;
    vec2 near = clamp(floor(cell) + 0.5, vec2(0.5), used - 0.5);
    vec2 corner = floor(cell - 0.5) + 0.5;
    vec3 nearLin = vec3(0.0), lo = vec3(1e30), hi = vec3(0.0);
    for (int k = 0; k < 4; ++k) {
        vec2 c = clamp(corner + vec2(k & 1, k >> 1), vec2(0.5), used - 0.5);
        vec3 s = max(textureLod(integrated, vec3(c / pc.grid.xy, w), 0.0).rgb, vec3(0.0)) *
                 (first / pc.slices.w);
        lo = min(lo, s);
        hi = max(hi, s);
        if (all(equal(c, near))) nearLin = s;
    }
    // What a pixel holds stays within the four columns' range widened by four times its width on
    // each side: a pixel between columns holds more or less than any of them (a glow's peak, a
    // thin shaft), but not without bound. A narrower pad cut point_fog's glow, no clamp left
    // window_room's outliers (docs/methods.md, "Still frames refined per pixel", has the figures).
    vec3 pad = 4.0 * (hi - lo);
    if (pc.history.z > 0.5) {
        // The kept grid's trilinear fetch at the pixel: what the history's detail is relative to.
        vec2 keptXy = columnCoordinates(p, vec2(0.0), used);
        vec3 base = max(gridAt(kept, vec3(keptXy, w), u, first).rgb, vec3(0.0)) / pc.slices.w;
        vec2 d = (cell - near) / pc.history.x;
        float weight = exp(-0.5 * dot(d, d));
        vec4 h = imageLoad(pixels, p);
        h.rgb = clamp(h.rgb + base, lo - pad, hi + pad);
        // A pixel the frame before left moving holds its fetch there, not a weight (below).
        if (h.a <= 0.0) h.a = pc.history.w;
        float carried = max(h.a + weight, 1e-6);
        vec3 gathered = (h.rgb * h.a + nearLin * weight) / carried;
        imageStore(pixelsOut, p, vec4(gathered - base, min(carried, pc.history.y)));
        lin = gathered;
    } else if (pc.history.y > 0.0) {
        // A frame that moved: the detail the pixel's surface had where the frame before saw it
        // (bilinear), a share of it added to this frame's fetch and clamped to this frame's range,
        // so that what was gathered while still fades out over frames instead of dropping at the
        // first that moves. The pixel leaves its fetch's mean (<= 0, as -mean) where a still
        // frame leaves its weight (> 0).
        vec3 v = pixelRayDirection(p);
        vec4 X = pc.previousFromCamera * vec4(v * rayLength(z, v), 1.0);
        vec2 q = ndcToPixel(X.xy / max(X.w, 1e-30)) - 0.5;
        vec4 h = vec4(0.0, 0.0, 0.0, pc.history.w);
        if (X.w > 0.0 && all(greaterThanEqual(q, vec2(0.0))) &&
            all(lessThanEqual(q, frame.screenSize.xy - 1.0))) {
            ivec2 q0 = ivec2(floor(q));
            ivec2 q1 = min(q0 + 1, ivec2(frame.screenSize.xy) - 1);
            vec2 f = q - vec2(q0);
            vec4 t00 = imageLoad(pixels, q0), t10 = imageLoad(pixels, ivec2(q1.x, q0.y));
            vec4 t01 = imageLoad(pixels, ivec2(q0.x, q1.y)), t11 = imageLoad(pixels, q1);
            vec4 r4 = mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
            vec3 r = r4.rgb;
            // Where the frame before moved too, its fetch (alpha <= 0) at the surface's point;
            // never a blend of a fetch and a weight.
            bool heldFetch = max(max(t00.a, t10.a), max(t01.a, t11.a)) <= 0.0;
            // The detail corrects the grid's fetch where its columns were, and the columns stay
            // on the screen while the surface moves: the further it moved, the less of the detail
            // still fits (a quarter of a froxel: 1 / e). On bench/froxels_flicker.json's camera
            // motion a half or a whole froxel left point_fog's glow flickering; ten steps at once
            // carried whole (no such fade) measured 1.44x the plain grid's error.
            float keep = pc.history.y * exp(-length(q - vec2(p)) / (0.25 * pc.grid.w));
            vec3 detail = keep * r;
            bool cameraMoved = pc.history.x > 0.0;  // its gathering width, else 0
            if (heldFetch && cameraMoved) {
                // Not in the first frame that moves: the still frames' image stays (see above).
                vec2 dd = (cell - near) / pc.history.x;
                float wg = exp(-0.5 * dot(dd, dd));
                vec3 shown = lin + detail;
                detail = (shown * kMovingMemory + nearLin * wg) / (kMovingMemory + wg) - lin;
            }
            if (heldFetch)
                detail = followFetch(r, detail, lin, -r4.a,
                                     cameraMoved ? kMovingDetailDrift : kDetailDrift);
            h.rgb = clamp(lin + detail, lo - pad, hi + pad) - lin;
            h.a = -meanOf(lin);
        }
        imageStore(pixelsOut, p, h);
        lin += h.rgb;
    } else {
        imageStore(pixelsOut, p, vec4(0.0, 0.0, 0.0, pc.history.w));
    }
#endif
    compositeWith(p, lin, vec3(g.a), false);
}
