// docs/model.md's non-uniform medium: the density factor m(x) that multiplies every coefficient,
// and the optical depth (the integral of m) along a straight segment, exact: the height fog's in
// closed form, a hard box's as its chord, a faded box's piecewise cubic by Simpson's rule on each
// piece. Only kMedia != 0 reads the frame's medium; with kMedia == 0 m is 1 and these fold away.
#ifndef LS_MEDIUM_GLSL
#define LS_MEDIUM_GLSL
#include "frame.glsl"
#include "math.glsl"

int fogVolumeCount() { return (kMedia & LS_MEDIA_VOLUMES) != 0 ? int(frame.medium.w) : 0; }
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
    if (e.w > 0.0) {
        vec3 w = clamp(inside / e.w, 0.0, 1.0);
        return w.x * w.y * w.z;
    }
    return all(greaterThanEqual(inside, vec3(0.0))) ? 1.0 : 0.0;
}

float densityAt(vec3 x) {
    if (kMedia == 0) return 1.0;
    float m = frame.medium.x * heightFactor(x.y);
    int n = fogVolumeCount();
    for (int i = 0; i < n; ++i) m += fogDensity(i) * fogWeightLocal(i, fogLocal(i, vec4(x, 1.0)));
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

// Box i's weight integrated along [0, l] of p + t d.
float fogVolumeDepth(int i, vec3 p, vec3 d, float l) {
    vec3 q = fogLocal(i, vec4(p, 1.0)), dq = fogLocal(i, vec4(d, 0.0));
    vec4 e = frame.fogVolumes[i][3];
    vec2 c = boxChord(q, dq, e.xyz, l);
    if (!(c.x < c.y)) return 0.0;
    if (e.w <= 0.0) return c.y - c.x;
    // Each factor is linear in t between the planes |q_j| = e_j - fade and q_j = 0: the product
    // is a cubic between consecutive crossings, which Simpson's rule integrates exactly.
    float cuts[9];
    int n = 0;
    for (int j = 0; j < 3; ++j) {
        if (abs(dq[j]) < 1e-20) continue;
        float inner = e[j] - e.w;
        for (int s = 0; s < 3; ++s) {
            float plane = s == 0 ? inner : s == 1 ? -inner : 0.0;
            if (s < 2 && inner <= 0.0) continue;
            float t = (plane - q[j]) / dq[j];
            if (t > c.x && t < c.y && n < 9) cuts[n++] = t;
        }
    }
    for (int a = 1; a < n; ++a) {  // insertion sort: at most 9
        float t = cuts[a];
        int b = a - 1;
        while (b >= 0 && cuts[b] > t) {
            cuts[b + 1] = cuts[b];
            --b;
        }
        cuts[b + 1] = t;
    }
    float sum = 0.0, t0 = c.x, w0 = fogWeightLocal(i, q + c.x * dq);
    for (int k = 0; k <= n; ++k) {
        float t1 = k < n ? cuts[k] : c.y;
        if (t1 <= t0) continue;
        float w1 = fogWeightLocal(i, q + t1 * dq);
        float wm = fogWeightLocal(i, q + (0.5 * (t0 + t1)) * dq);
        sum += (t1 - t0) * (w0 + 4.0 * wm + w1) / 6.0;
        t0 = t1;
        w0 = w1;
    }
    return sum;
}

// The integral of m along [p, p + l d], d unit.
float opticalDepth(vec3 p, vec3 d, float l) {
    if (kMedia == 0) return l;
    if (!(l > 0.0)) return 0.0;
    float tau = frame.medium.x * heightDepth(p, d, l);
    int n = fogVolumeCount();
    for (int i = 0; i < n; ++i) tau += fogDensity(i) * fogVolumeDepth(i, p, d, l);
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
    int n = fogVolumeCount();
    for (int i = 0; i < n; ++i) {
        vec2 c = boxChord(fogLocal(i, vec4(p, 1.0)), fogLocal(i, vec4(v, 0.0)),
                          frame.fogVolumes[i][3].xyz, len);
        if (c.x < c.y) {
            lo = min(lo, c.x);
            hi = max(hi, c.y);
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
