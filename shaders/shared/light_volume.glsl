// Where a camera ray can receive light: the spot's cone (single nappe) within its range, and the
// part of the ray inside the shadow map's frustum; in clear air, only where a fog volume is.
// Intervals are [t0, t1] in metres along the ray; an empty one has t0 >= t1.
#ifndef LS_LIGHT_VOLUME_GLSL
#define LS_LIGHT_VOLUME_GLSL
#include "frame.glsl"
#include "medium.glsl"

void clipHalfLine(float a, float b, inout float t0, inout float t1) {
    // Keeps the t where a + b t >= 0.
    if (abs(b) < 1e-30) {
        if (a < 0.0) t1 = t0;
        return;
    }
    float r = -a / b;
    if (b > 0.0) t0 = max(t0, r); else t1 = min(t1, r);
}

// Ray C + t v (v unit) against the sphere |P - L| <= R.
void clipSphere(vec3 co, vec3 v, float R, inout float t0, inout float t1) {
    float b = dot(co, v);
    // Distance from the line to the centre from the cross product, never |co|^2 - b^2.
    vec3 perp = co - b * v;
    float disc = R * R - dot(perp, perp);
    if (disc < 0.0) { t1 = t0; return; }
    float h = sqrt(disc);
    t0 = max(t0, -b - h);
    t1 = min(t1, -b + h);
}

// Ray against the single cone of half-angle acos(cosA) around unit axis a with apex at the light.
// co = C - L. The nappe is convex for angles below 90 degrees, so the result is one interval.
void clipCone(vec3 co, vec3 v, vec3 a, float cosA, inout float t0, inout float t1) {
    float c2 = cosA * cosA;
    float dv = dot(v, a), dco = dot(co, a);
    // g(t) = (D.a)^2 - c2 |D|^2 with D = co + t v; inside where g >= 0 and D.a >= 0.
    float A = dv * dv - c2;
    float B = dv * dco - c2 * dot(v, co);
    float Cc = dco * dco - c2 * dot(co, co);
    clipHalfLine(dco, dv, t0, t1);  // the lit nappe only
    if (t0 >= t1) return;
    if (abs(A) < 1e-7) {
        // Parallel to a generator: g is linear, 2B t + Cc >= 0.
        clipHalfLine(Cc, 2.0 * B, t0, t1);
        return;
    }
    float disc = B * B - A * Cc;
    if (disc < 0.0) {
        if (A < 0.0) t1 = t0;  // g < 0 everywhere
        return;                // g > 0 everywhere (only with A > 0, inside the double cone)
    }
    float s = sqrt(disc);
    float q = -(B + sign(B) * s);  // stable roots
    float r1 = q / A, r2 = abs(q) > 1e-30 ? Cc / q : r1;
    float lo = min(r1, r2), hi = max(r1, r2);
    if (A < 0.0) {
        t0 = max(t0, lo);
        t1 = min(t1, hi);
    } else {
        // g >= 0 outside (lo, hi). Within the half-space D.a >= 0 that is the lit nappe, which is
        // convex, so only one of the two pieces can be non-empty; near the apex, where rounding can
        // leave both, keep the longer.
        float left1 = min(t1, lo), right0 = max(t0, hi);
        float leftLen = left1 - t0, rightLen = t1 - right0;
        if (leftLen <= 0.0 && rightLen <= 0.0) t1 = t0;
        else if (leftLen >= rightLen) t1 = left1;
        else t0 = right0;
    }
}

// The part of [0, S] that the light can reach: all of it for a directional light, the sphere of
// its range for a point light (all of it without one), the cone within the range for a spot. In
// clear air (a non-uniform medium of density 0) nothing scatters outside the fog volumes, so the
// part is cut to the stretch from the first volume's entry to the last one's exit: every march
// walks only that (beginInscatter takes the optical depth up to its start).
void lightInterval(vec3 C, vec3 v, float S, out float t0, out float t1) {
    t0 = 0.0;
    t1 = S;
    // A point light without a range (1e30) clips nothing (its square would overflow).
    if (kLightType != LIGHT_DIRECTIONAL &&
        !(kLightType == LIGHT_POINT && frame.lightIntensity.w >= 1e18)) {
        vec3 co = C - frame.lightPos.xyz;
        clipSphere(co, v, frame.lightIntensity.w, t0, t1);
        if (kLightType == LIGHT_SPOT && t0 < t1)
            clipCone(co, v, frame.lightDir.xyz, frame.lightDir.w, t0, t1);
    }
    clipToMedium(C, v, t0, t1);
}

// The part of [t0, t1] inside the shadow map's frustum (-w <= x, y <= w, 0 <= z <= w, w > 0): each
// bound is linear in t along the ray in clip space.
void clipToFrustum(mat4 M, vec3 C, vec3 v, inout float t0, inout float t1) {
    vec4 a = M * vec4(C, 1.0);
    vec4 b = M * vec4(v, 0.0);
    clipHalfLine(a.w + a.x, b.w + b.x, t0, t1);
    clipHalfLine(a.w - a.x, b.w - b.x, t0, t1);
    clipHalfLine(a.w + a.y, b.w + b.y, t0, t1);
    clipHalfLine(a.w - a.y, b.w - b.y, t0, t1);
    clipHalfLine(a.z, b.z, t0, t1);
    clipHalfLine(a.w - a.z, b.w - b.z, t0, t1);
    clipHalfLine(a.w - 1e-6 * abs(a.w), b.w, t0, t1);
}

void clipToShadowFrustum(vec3 C, vec3 v, inout float t0, inout float t1) {
    clipToFrustum(frame.lightViewProj, C, v, t0, t1);
}

// The part of [t0, t1] where cube face `face` (+X, -X, +Y, -Y, +Z, -Z) is the major axis of
// P - L: s D[axis] >= |D[other]| for both other axes, four half-spaces through the light. The six
// regions tile space without overlap, as Vulkan's cube face selection does.
void clipToCubeFaceRegion(vec3 C, vec3 v, int face, inout float t0, inout float t1) {
    vec3 a = C - frame.lightPos.xyz;
    int axis = face >> 1;
    float s = (face & 1) == 0 ? 1.0 : -1.0;
    for (int k = 1; k <= 2; ++k) {
        int o = (axis + k) % 3;
        clipHalfLine(s * a[axis] - a[o], s * v[axis] - v[o], t0, t1);
        clipHalfLine(s * a[axis] + a[o], s * v[axis] + v[o], t0, t1);
    }
}

#endif
