// Per-pixel ray marching through the shadow map, one step per texel crossed (seed 000's starting
// point): the brute-force method and the epipolar fix-up. The ray is clipped to the light's volume
// and to the shadow map's frustum; the parts outside the frustum are lit and integrated in closed
// form. Attributes are interpolated perspective-correctly in light space (1/w and d/w are affine).
#ifndef LS_MARCH_GLSL
#define LS_MARCH_GLSL
#include "integrate.glsl"
#include "light_color.glsl"
#include "light_volume.glsl"
#include "shadow.glsl"

// A counting variant of a march (ray_march.frag with LS_COUNT_STEPS) defines it to count look-ups.
#ifndef LS_COUNT_LOOKUP
#define LS_COUNT_LOOKUP()
#endif

// A stretch of a ray inside the shadow map's frustum, parameterised by a in [0, 1], affine in the
// shadow map's image plane: its distance is perspective-correct from f0 to f1 (1/w and d/w are
// affine in a), its standard depth mix(z0, z1, a) (depth over w is affine too).
struct FrustumSegment {
    float f0, f1;    // metres along the camera ray
    float iw0, iw1;  // 1/w at both ends
    float z0, z1;    // standard depth at both ends
};

float segmentDistance(FrustumSegment s, float a) {
    if (a >= 1.0) return s.f1;
    return mix(s.f0 * s.iw0, s.f1 * s.iw1, a) / mix(s.iw0, s.iw1, a);
}

// The part [aA, aB] of s seen through one footprint of the shadow map. Each texel of the footprint
// lights the points in front of its depth, and the ray's depth is monotonic in a, so a texel that
// lights one end of the part and not the other changes once, where the ray passes its depth: the
// part is split there. A part no texel changes on is one step with the visibility at its end, as
// marchFrustumSegmentOf takes it. The split matters where a long stretch of ray projects into one
// texel: a ray towards or away from the light (the light's own screen position: its ray passes
// through a point light, and behind it the end of the ray, a surface that the map itself holds,
// would otherwise decide the whole stretch with half the light's glow on it).
// Returns the crossings sorted along the ray (aB for a texel not passed) and whether there is one.
bool footprintCrossings(FrustumSegment s, ShadowFootprint fp, float aA, float aB, out vec4 c) {
    float zA = compareDepth(mix(s.z0, s.z1, aA)), zB = compareDepth(mix(s.z0, s.z1, aB));
    bvec4 litA = lessThanEqual(vec4(zA), fp.depth), litB = lessThanEqual(vec4(zB), fp.depth);
    c = vec4(aB);
    if (!fp.inside || litA == litB) return false;
    for (int k = 0; k < 4; ++k)
        if (litA[k] != litB[k]) c[k] = mix(aA, aB, clamp((fp.depth[k] - zA) / (zB - zA), 0.0, 1.0));
    c.xy = vec2(min(c.x, c.y), max(c.x, c.y));
    c.zw = vec2(min(c.z, c.w), max(c.z, c.w));
    c.xz = vec2(min(c.x, c.z), max(c.x, c.z));
    c.yw = vec2(min(c.y, c.w), max(c.y, c.w));
    c.yz = vec2(min(c.y, c.z), max(c.y, c.z));
    return true;
}

// Adds the pieces of one step of a march, [aA, aB] of s: the crossings from index first on (0, or
// 4 for none), each lit through fp at its middle, then the rest lit through fp at aB (times
// color), or skipped whole where shadowed. A march calls it once per step, with a first it cannot
// know when compiled: lavapipe runs every branch of a loop's body whichever its lanes take, so
// the body should hold advance and skip once each, not once per call site or unrolled iteration.
void advancePieces(inout Inscatter acc, FrustumSegment s, ShadowFootprint fp, vec3 color,
                   vec4 cuts, int first, float aA, float aB, bool shadowed) {
    float a = aA;
    for (int k = first; k < 5; ++k) {
        float c = k < 4 ? cuts[k] : aB;
        if (k < 4 && c <= a) continue;
        float z = compareDepth(mix(s.z0, s.z1, k < 4 ? 0.5 * (a + c) : aB));
        float d = segmentDistance(s, c);
        advanceOrSkip(acc, d, footprintVisibility(fp, z) * color, shadowed);
        a = c;
    }
}

void advanceThroughFootprint(inout Inscatter acc, FrustumSegment s, ShadowFootprint fp, float aA,
                             float aB, vec3 color) {
    vec4 cuts;
    int first = footprintCrossings(s, fp, aA, aB, cuts) ? 0 : 4;
    advancePieces(acc, s, fp, color, cuts, first, aA, aB, false);
}

// Adds [f0, f1] (inside the shadow map's frustum) to acc, one step per texel crossed (at most
// maxSteps when that is not 0), each step's visibility taken at its end; with splitAtDepth, each
// step split where the ray passes a texel's depth (advanceThroughFootprint: the epipolar march's
// rays that leave their slice's line).
void marchFrustumSegmentOf(mat4 M, inout Inscatter acc, vec3 C, vec3 v, float f0, float f1,
                           uint maxSteps, bool splitAtDepth) {
    vec4 X0 = M * vec4(C + f0 * v, 1.0);
    vec4 X1 = M * vec4(C + f1 * v, 1.0);
    vec2 uv0 = X0.xy / X0.w * 0.5 + 0.5, uv1 = X1.xy / X1.w * 0.5 + 0.5;
    float z0 = toStandardDepth(X0.z / X0.w), z1 = toStandardDepth(X1.z / X1.w);
    float iw0 = 1.0 / X0.w, iw1 = 1.0 / X1.w;
    FrustumSegment s = FrustumSegment(f0, f1, iw0, iw1, z0, z1);
    vec2 span = abs(uv1 - uv0) * frame.shadowInfo.x;
    uint n = uint(max(1.0, ceil(max(span.x, span.y))));
    if (maxSteps > 0u) n = min(n, maxSteps);
    for (uint k = 1u; k <= n; ++k) {
        float a = float(k) / float(n);
        vec2 uv = mix(uv0, uv1, a);
        LS_COUNT_LOOKUP();
        if (splitAtDepth) {
            advanceThroughFootprint(acc, s, shadowFootprint(uv), float(k - 1u) / float(n), a,
                                    lightColorAt(uv));
            continue;
        }
        float d = k == n ? f1 : mix(f0 * iw0, f1 * iw1, a) / mix(iw0, iw1, a);
        advance(acc, d, shadowVisibility(uv, mix(z0, z1, a)) * lightColorAt(uv));
    }
}

void marchFrustumSegment(inout Inscatter acc, vec3 C, vec3 v, float f0, float f1, uint maxSteps,
                         bool splitAtDepth) {
    marchFrustumSegmentOf(frame.lightViewProj, acc, C, v, f0, f1, maxSteps, splitAtDepth);
}

#if defined(LS_NO_SHADOW_MAP) && LS_NO_SHADOW_MAP
// Without a shadow map only the light color varies along the ray, and it is projected as the
// methods that sample points project it (light_at.glsl: in front of the light, within the
// frustum's sides; it has no near or far plane): the ray is clipped to those planes alone, and its
// pieces stay within [0, 1] in the color's image.
void clipToColorProjection(vec3 C, vec3 v, inout float t0, inout float t1) {
    vec4 a = frame.lightViewProj * vec4(C, 1.0);
    vec4 b = frame.lightViewProj * vec4(v, 0.0);
    clipHalfLine(a.w + a.x, b.w + b.x, t0, t1);
    clipHalfLine(a.w - a.x, b.w - b.x, t0, t1);
    clipHalfLine(a.w + a.y, b.w + b.y, t0, t1);
    clipHalfLine(a.w - a.y, b.w - b.y, t0, t1);
    clipHalfLine(a.w - 1e-6 * abs(a.w), b.w, t0, t1);
}
#endif

#if defined(LS_NO_SHADOW_MAP) && LS_NO_SHADOW_MAP
// Adds [f0, f1] (inside the color's projection) to acc through the light color alone. The color is
// bilinear between texel centres, so the ray is cut where it crosses a row or a column of them:
// within each piece the color is smooth, and its value at the piece's middle is right to second
// order (at a step's end, a one-texel lead of a stained-glass window would be hit or missed whole).
// That is at most two pieces per texel crossed, each integrated in closed form.
void marchColorSegment(inout Inscatter acc, vec3 C, vec3 v, float f0, float f1) {
    vec4 X0 = frame.lightViewProj * vec4(C + f0 * v, 1.0);
    vec4 X1 = frame.lightViewProj * vec4(C + f1 * v, 1.0);
    vec2 uv0 = X0.xy / X0.w * 0.5 + 0.5, uv1 = X1.xy / X1.w * 0.5 + 0.5;
    float iw0 = 1.0 / X0.w, iw1 = 1.0 / X1.w;
    // In texel-centre units the rows and columns of centres are the integers.
    vec2 p0 = uv0 * frame.shadowInfo.x - 0.5, dp = (uv1 - uv0) * frame.shadowInfo.x;
    vec2 next = vec2(2.0), inc = vec2(2.0);  // a of the next crossing per axis, a between two
    for (int k = 0; k < 2; ++k) {
        if (abs(dp[k]) < 1e-12) continue;
        float line = dp[k] > 0.0 ? floor(p0[k]) + 1.0 : ceil(p0[k]) - 1.0;
        next[k] = (line - p0[k]) / dp[k];
        inc[k] = 1.0 / abs(dp[k]);
    }
    // The closed form weighs a piece by the light reaching the camera from it, which extinction
    // tilts towards the piece's near end: a piece more than kColorPieceDepth optical depth long is
    // cut further (at most 8 parts), so that its color is not taken at the wrong middle (on a sun's
    // long sky rays through a coarse cookie that was most of the error).
    const float kColorPieceDepth = 0.05;
    float betaMax = max(frame.betaT.r, max(frame.betaT.g, frame.betaT.b));
    float a = 0.0, da = f0;
    int guard = 2 * int(frame.shadowInfo.x) + 4;
    while (a < 1.0 && guard-- > 0) {
        float b = min(min(next.x, next.y), 1.0);
        float db = b >= 1.0 ? f1 : mix(f0 * iw0, f1 * iw1, b) / mix(iw0, iw1, b);
        int m = int(clamp(ceil((db - da) * betaMax / kColorPieceDepth), 1.0, 8.0));
        for (int j = 1; j <= m; ++j) {
            float e = mix(a, b, float(j) / float(m));
            float de = j == m ? db : mix(f0 * iw0, f1 * iw1, e) / mix(iw0, iw1, e);
            LS_COUNT_LOOKUP();
            advance(acc, de, lightColorAt(mix(uv0, uv1, mix(a, b, (float(j) - 0.5) / float(m)))));
        }
        if (next.x <= b) next.x += inc.x;
        if (next.y <= b) next.y += inc.y;
        a = b;
        da = db;
    }
    advance(acc, f1, lightColorAt(uv1));  // what the guard left, if anything
}
#endif

// Lin along C + d v, d in [0, S]; maxSteps 0 means one step per texel.
vec3 marchRay(vec3 C, vec3 v, float S, uint maxSteps) {
    float t0, t1;
    lightInterval(C, v, S, t0, t1);
    if (!(t0 < t1)) return vec3(0.0);
    Inscatter acc = beginInscatter(C, v, t0);
    float f0 = t0, f1 = t1;
#if defined(LS_NO_SHADOW_MAP) && LS_NO_SHADOW_MAP
    clipToColorProjection(C, v, f0, f1);
    if (f0 < f1) {
        advance(acc, f0, vec3(1.0));
        marchColorSegment(acc, C, v, f0, f1);
    }
#else
    clipToShadowFrustum(C, v, f0, f1);
    if (f0 < f1) {
        advance(acc, f0, vec3(1.0));
        marchFrustumSegment(acc, C, v, f0, f1, maxSteps, false);
    }
#endif
    advance(acc, t1, vec3(1.0));
    return finishInscatter(acc, v);
}

#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
// A point light's cube map: the ray is cut where the major axis of P - L changes (one interval
// per face, since each face's region is a convex cone), each interval is clipped to its face's
// frustum and marched through that face's layer, one step per texel; what lies outside every
// frustum (within a near plane, beyond a far plane) is lit, as outside a spot's map.
vec3 marchRayCube(vec3 C, vec3 v, float S, uint maxSteps) {
    float t0, t1;
    lightInterval(C, v, S, t0, t1);
    if (!(t0 < t1)) return vec3(0.0);
    Inscatter acc = beginInscatter(C, v, t0);
    float lo[6], hi[6];
    for (int f = 0; f < 6; ++f) {
        lo[f] = t0;
        hi[f] = t1;
        clipToCubeFaceRegion(C, v, f, lo[f], hi[f]);
        clipToFrustum(frame.cubeFaceViewProj[f], C, v, lo[f], hi[f]);
    }
    float done = t0;
    for (int n = 0; n < 6; ++n) {
        // The nearest interval not marched yet (at most three are non-empty).
        int next = -1;
        for (int f = 0; f < 6; ++f)
            if (lo[f] < hi[f] && (next < 0 || lo[f] < lo[next])) next = f;
        if (next < 0) break;
        float f0 = max(lo[next], done), f1 = hi[next];
        lo[next] = hi[next];
        if (!(f0 < f1)) continue;
        advance(acc, f0, vec3(1.0));
        shadowFace = next;
        marchFrustumSegmentOf(frame.cubeFaceViewProj[next], acc, C, v, f0, f1, maxSteps, false);
        done = f1;
    }
    advance(acc, t1, vec3(1.0));
    return finishInscatter(acc, v);
}
#endif

#endif
