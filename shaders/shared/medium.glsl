// docs/model.md's non-uniform medium: the density factor m(x) that multiplies every coefficient,
// and the optical depth (the integral of m) along a straight segment, exact: the height fog's in
// closed form, a hard box's as its chord, a faded box's piecewise cubic by Simpson's rule on each
// piece. Only kMedia != 0 reads the frame's medium; with kMedia == 0 m is 1 and these fold away.
#ifndef LS_MEDIUM_GLSL
#define LS_MEDIUM_GLSL
#include "frame.glsl"
#include "math.glsl"

// A loop over the volumes sits inside `if (kFogVolumes)`: a count of 0 chosen by the constant
// alone leaves the loop's body in lavapipe's shader, where it made a sun's ray march 5x slower.
const bool kFogVolumes = (kMedia & LS_MEDIA_VOLUMES) != 0;
// Soft-edged volumes' piecewise cubics, compiled only where a volume has a fade: for hard boxes
// alone their code made a spot's ray march 1.9x slower on lavapipe, which runs every branch.
const bool kFogFades = (kMedia & LS_MEDIA_FADES) != 0;
int fogVolumeCount() { return kFogVolumes ? int(frame.medium.w) : 0; }
float fogDensity(int i) { return frame.fogDensity[i / 4][i % 4]; }

// The height fog's factor h(y) (without d0).
float heightFactor(float y) {
    if ((kMedia & LS_MEDIA_HEIGHT_FOG) == 0) return 1.0;
    return exp(-frame.medium.z * max(0.0, y - frame.medium.y));
}

vec3 fogLocal(int i, vec4 x) {
    mat4 b = frame.fogVolumes[i];
    return vec3(dot(b[0], x), dot(b[1], x), dot(b[2], x));
}

// b_i at a point given in the box's local coordinates.
float fogWeightLocal(int i, vec3 q) {
    vec4 e = frame.fogVolumes[i][3];
    vec3 inside = e.xyz - abs(q);
    if (kFogFades && e.w > 0.0) {
        vec3 w = clamp(inside / e.w, 0.0, 1.0);
        return w.x * w.y * w.z;
    }
    return all(greaterThanEqual(inside, vec3(0.0))) ? 1.0 : 0.0;
}

float densityAt(vec3 x) {
    if (kMedia == 0) return 1.0;
    float m = frame.medium.x * heightFactor(x.y);
    if (kFogVolumes) {
        int n = fogVolumeCount();
        for (int i = 0; i < n; ++i)
            m += fogDensity(i) * fogWeightLocal(i, fogLocal(i, vec4(x, 1.0)));
    }
    return m;
}

// -expm1(-x) / x, 1 at 0: the mean of exp(-u) over [0, x].
float meanDecay(float x) {
    return x < 1e-4 ? 1.0 - 0.5 * x : -expm1f(-x) / x;
}

// The height part's integral along [p, p + l d] (d unit): full density at and below the base
// height; above it the lower end's factor times l meanDecay(k |dy| l). Never 0 x inf: every
// factor is at most 1 and the length finite.
float heightDepth(vec3 p, vec3 d, float l) {
    if ((kMedia & LS_MEDIA_HEIGHT_FOG) == 0) return l;
    float k = frame.medium.z, h0 = frame.medium.y;
    float ya = p.y, yb = p.y + d.y * l;
    float lo = min(ya, yb), hi = max(ya, yb);
    if (hi <= h0) return l;
    if (lo >= h0) return exp(-k * (lo - h0)) * l * meanDecay(k * (hi - lo));
    float above = l * (hi - h0) / (hi - lo);  // the part above the base height
    return (l - above) + above * meanDecay(k * (hi - h0));
}

// Where [0, l] of q + t dq lies within |q_j| <= e_j on every axis (t0 > t1: nowhere).
vec2 boxChord(vec3 q, vec3 dq, vec3 e, float l) {
    float t0 = 0.0, t1 = l;
    for (int j = 0; j < 3; ++j) {
        if (abs(dq[j]) < 1e-20) {
            if (abs(q[j]) > e[j]) return vec2(1.0, 0.0);
            continue;
        }
        float a = (-e[j] - q[j]) / dq[j], b = (e[j] - q[j]) / dq[j];
        t0 = max(t0, min(a, b));
        t1 = min(t1, max(a, b));
    }
    return vec2(t0, t1);
}

// Orders a and b (a sorting network's comparator).
#define LS_ORDER(a, b)          \
    {                           \
        float lo_ = min(a, b);  \
        b = max(a, b);          \
        a = lo_;                \
    }

// A soft-edged box's weight integrated over the chord c of q + t dq (box-local). Each factor
// clamp((e_j - |q_j|) / fade, 0, 1) is linear in t between its kinks, |q_j| = e_j - fade where that
// is above 0 and q_j = 0 where it is not, so the product is a cubic between consecutive kinks, which
// Simpson's rule integrates exactly. The (at most 6) kinks are sorted by a network and the pieces
// taken in a fixed order: no array indexed at run time and no branch, both of which lavapipe pays
// for on every lane whether it takes them or not.
float fadedVolumeDepth(int i, vec3 q, vec3 dq, vec4 e, vec2 c) {
    vec3 inner = e.xyz - e.w;
    bvec3 parallel = lessThan(abs(dq), vec3(1e-20));
    vec3 inv = 1.0 / mix(dq, vec3(1.0), parallel);
    bvec3 ramps = greaterThan(inner, vec3(0.0));
    vec3 ka = mix(-q, inner - q, ramps) * inv;  // q_j = 0, or q_j = inner_j
    vec3 kb = (-inner - q) * inv;               // q_j = -inner_j, where inner_j > 0
    ka = mix(clamp(ka, c.x, c.y), vec3(c.y), parallel);
    kb = mix(clamp(kb, c.x, c.y), vec3(c.y), bvec3(parallel.x || !ramps.x, parallel.y || !ramps.y,
                                                  parallel.z || !ramps.z));
    float t0 = ka.x, t1 = ka.y, t2 = ka.z, t3 = kb.x, t4 = kb.y, t5 = kb.z;
    LS_ORDER(t0, t5) LS_ORDER(t1, t3) LS_ORDER(t2, t4) LS_ORDER(t1, t2) LS_ORDER(t3, t4)
    LS_ORDER(t0, t3) LS_ORDER(t2, t5) LS_ORDER(t0, t1) LS_ORDER(t2, t3) LS_ORDER(t4, t5)
    LS_ORDER(t1, t2) LS_ORDER(t3, t4)
    float cuts[8] = float[8](c.x, t0, t1, t2, t3, t4, t5, c.y);
    float sum = 0.0, w0 = fogWeightLocal(i, q + c.x * dq);
    for (int k = 0; k < 7; ++k) {  // unrolled: constant indices
        float a = cuts[k], b = cuts[k + 1];
        float w1 = fogWeightLocal(i, q + b * dq);
        float wm = fogWeightLocal(i, q + (0.5 * (a + b)) * dq);
        sum += (b - a) * (w0 + 4.0 * wm + w1) * (1.0 / 6.0);
        w0 = w1;
    }
    return sum;
}
#undef LS_ORDER

// Box i's weight integrated along [0, l] of p + t d.
float fogVolumeDepth(int i, vec3 p, vec3 d, float l) {
    vec3 q = fogLocal(i, vec4(p, 1.0)), dq = fogLocal(i, vec4(d, 0.0));
    vec4 e = frame.fogVolumes[i][3];
    vec2 c = boxChord(q, dq, e.xyz, l);
    if (!(c.x < c.y)) return 0.0;
    if (!kFogFades || e.w <= 0.0) return c.y - c.x;
    return fadedVolumeDepth(i, q, dq, e, c);
}

// The integral of m along [p, p + l d], d unit.
float opticalDepth(vec3 p, vec3 d, float l) {
    if (kMedia == 0) return l;
    if (!(l > 0.0)) return 0.0;
    float tau = frame.medium.x * heightDepth(p, d, l);
    if (kFogVolumes) {
        int n = fogVolumeCount();
        for (int i = 0; i < n; ++i) tau += fogDensity(i) * fogVolumeDepth(i, p, d, l);
    }
    return tau;
}

// Where m can be above 0 on [t0, t1] of C + t v: in clear air (d0 = 0) only within the fog
// volumes, so the stretch from the first volume's entry to the last one's exit (empty, t1 <= t0,
// when the ray meets none); elsewhere unchanged. A method that spreads a fixed number of samples
// over a ray spends them where the medium is.
void clipToMedium(vec3 C, vec3 v, inout float t0, inout float t1) {
    if (kMedia == 0 || frame.medium.x > 0.0 || !(t0 < t1)) return;
    vec3 p = C + t0 * v;
    float len = t1 - t0, lo = len, hi = 0.0;
    if (kFogVolumes) {
        int n = fogVolumeCount();
        for (int i = 0; i < n; ++i) {
            vec2 c = boxChord(fogLocal(i, vec4(p, 1.0)), fogLocal(i, vec4(v, 0.0)),
                              frame.fogVolumes[i][3].xyz, len);
            if (c.x < c.y) {
                lo = min(lo, c.x);
                hi = max(hi, c.y);
            }
        }
    }
    t1 = t0 + hi;
    t0 = t0 + min(lo, hi);
}

// The optical depth from x to the light at L (a point or spot light's path).
float opticalDepthTo(vec3 x, vec3 L) {
    vec3 toL = L - x;
    float r = length(toL);
    return r > 0.0 ? opticalDepth(x, toL / r, r) : 0.0;
}

#endif
