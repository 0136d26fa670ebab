// The screen side of epipolar sampling: the shrunk boundary of the light's screen rectangle,
// where each slice's line leaves it, and the inverse (which slice a pixel lies on).
#ifndef LS_EPIPOLAR_GEOMETRY_GLSL
#define LS_EPIPOLAR_GEOMETRY_GLSL
#include "epipolar_constants.glsl"
#include "frame.glsl"

// The centres of the outer pixels of the light's screen rectangle: seed 000's optimised placement
// ([-1 + 1/W, 1 - 1/W] x [-1 + 1/H, 1 - 1/H] on the whole screen), on the part of the screen
// its rays may cross (epipolar.bounds).
vec2 boundaryLo() { return epipolar.bounds.xy; }
vec2 boundaryHi() { return epipolar.bounds.zw; }

bool insideBoundary(vec2 p, float eps) {
    return all(greaterThanEqual(p, boundaryLo() - eps)) && all(lessThanEqual(p, boundaryHi() + eps));
}

// Corners in the order the slices walk around the boundary.
vec2 boundaryCorner(int i) {
    vec2 lo = boundaryLo(), hi = boundaryHi();
    if (i == 0) return lo;
    if (i == 1) return vec2(hi.x, lo.y);
    if (i == 2) return hi;
    return vec2(lo.x, hi.y);
}

vec2 edgeOutwardNormal(int edge) {
    if (edge == 0) return vec2(0.0, -1.0);
    if (edge == 1) return vec2(1.0, 0.0);
    if (edge == 2) return vec2(0.0, 1.0);
    return vec2(-1.0, 0.0);
}

// The point of the boundary at border coordinate u in [0, 4): edge floor(u), walked from its corner.
vec2 borderPoint(float u, out int edge) {
    edge = min(int(u), 3);
    return mix(boundaryCorner(edge), boundaryCorner((edge + 1) & 3), u - float(edge));
}

// Where the line of the light's slice `slice` meets the boundary: the border is divided into
// epipolar.window.y slices, an equal share per edge, and the light's are epipolar.window.x onwards.
vec2 sliceExitPoint(int slice, out int edge) {
    int border = int(epipolar.window.y);
    int g = (slice + int(epipolar.window.x)) % border;
    return borderPoint((float(g) + 0.5) / epipolar.window.y * 4.0, edge);
}

// Continuous border slice coordinate of a boundary point on `edge` (inverse of sliceExitPoint
// before the window: the light's slice is this less epipolar.window.x, modulo the border's).
float sliceOfExitPoint(vec2 e, int edge) {
    vec2 lo = boundaryLo(), hi = boundaryHi();
    float f;
    if (edge == 0) f = (e.x - lo.x) / (hi.x - lo.x);
    else if (edge == 1) f = (e.y - lo.y) / (hi.y - lo.y);
    else if (edge == 2) f = (hi.x - e.x) / (hi.x - lo.x);
    else f = (hi.y - e.y) / (hi.y - lo.y);
    return (float(edge) + clamp(f, 0.0, 1.0)) / 4.0 * epipolar.window.y - 0.5;
}

// The light's slice of border slice `g` in [-1, 2 border): in [0, epipolar.sampling.x) when the
// window holds it.
int windowSlice(int g) {
    int border = int(epipolar.window.y);
    int slice = g - int(epipolar.window.x);
    slice += slice < 0 ? border : 0;
    return slice >= border ? slice - border : slice;
}

// The parameter range where o + t d is inside the boundary (tNear > tFar when it misses).
void boundaryRange(vec2 o, vec2 d, out float tNear, out float tFar, out int farEdge) {
    vec2 lo = boundaryLo(), hi = boundaryHi();
    vec2 inv = 1.0 / mix(d, vec2(1e-20), lessThan(abs(d), vec2(1e-20)));
    vec2 ta = (lo - o) * inv, tb = (hi - o) * inv;
    vec2 tn = min(ta, tb), tf = max(ta, tb);
    tNear = max(tn.x, tn.y);
    tFar = min(tf.x, tf.y);
    if (tf.x < tf.y) farEdge = d.x > 0.0 ? 1 : 3;
    else farEdge = d.y > 0.0 ? 2 : 0;
}

const float INVALID_SLICE = -100.0;

#endif
