#include "camera_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "field_checks.h"
#include "matrix_checks.h"
#include "rendergraph/format_info.h"

namespace lightscatter::detail {
namespace {

// The planes the projection puts at depth 0 and 1, read from its z and w rows on the view axis
// (the point (0, 0, -t) lands at depth (a (-t) + b) / (c (-t) + d)): distances in front of the
// camera, +inf for a depth the projection reaches only at infinity.
struct DerivedPlanes {
    double atDepth0 = 0, atDepth1 = 0;
};

DerivedPlanes derivePlanes(const glm::mat4& p) {
    const double a = p[2][2], b = p[3][2], c = p[2][3], d = p[3][3];
    auto distanceAt = [&](double depth) {
        const double den = a - depth * c;  // z (a - depth c) = depth d - b, z = -distance
        const double num = depth * d - b;
        if (den == 0.0)
            return num == 0.0 ? std::numeric_limits<double>::quiet_NaN()
                              : std::numeric_limits<double>::infinity();
        return -num / den;
    };
    return {distanceAt(0.0), distanceAt(1.0)};
}

// The view is a rotation and a translation: view-space distances are the world's metres, which
// the planes read from the projection and every ray length rely on. Its camera lies within
// limits::kMaxLength of the origin on each axis.
void checkView(const glm::mat4& view) {
    const glm::dmat4 v(view);
    const glm::dmat3 r(v);
    const glm::dmat3 rtr = glm::transpose(r) * r;
    double off = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            off = std::max(off, std::fabs(rtr[i][j] - (i == j ? 1.0 : 0.0)));
    if (!(off <= 1e-3) || std::fabs(v[0][3]) > 1e-6 || std::fabs(v[1][3]) > 1e-6 ||
        std::fabs(v[2][3]) > 1e-6 || std::fabs(v[3][3] - 1.0) > 1e-6)
        fail("camera.view is not a rotation and a translation (its rotation part is " + num(off) +
             " off orthonormal, or its last row is not 0 0 0 1): view-space distances must be "
             "metres");
    const glm::dvec3 position = -(glm::transpose(r) * glm::dvec3(v[3]));
    for (int i = 0; i < 3; ++i)
        if (!(std::fabs(position[i]) <= limits::kMaxLength))
            fail("camera.view puts the camera at " + num(position[i]) + " on axis " +
                 std::to_string(i) + ": must be within " +
                 rangeText(-limits::kMaxLength, limits::kMaxLength) +
                 " m (lightscatter.h, limits::kMaxLength)");
}

// The plugin's rays all start at the camera, as a perspective projection's do: clip w is the
// distance along the view axis, w row (0, 0, -1, 0) up to scale (jitter and off-centre frusta
// change other rows). An orthographic projection (w row 0 0 0 1) has parallel rays; taken as
// one, the methods would each misread it differently (epipolar and brute force differed by 21%).
// A w row (0, 0, +1, 0) looks down +Z, which the near-plane check names.
void checkPerspective(const glm::mat4& p) {
    const double c = std::fabs(double(p[2][3]));
    const double off = std::max(
        {std::fabs(double(p[0][3])), std::fabs(double(p[1][3])), std::fabs(double(p[3][3]))});
    if (c > 0.0 && off <= 1e-6 * c) return;
    fail(
        "camera.projection is not a perspective projection: its w row (P[0][3], P[1][3], "
        "P[2][3], P[3][3]) is (" +
        num(p[0][3]) + ", " + num(p[1][3]) + ", " + num(p[2][3]) + ", " + num(p[3][3]) + ")" +
        (c == 0.0 && p[3][3] != 0.0f ? ", an orthographic projection's" : "") +
        "; the plugin's rays start at the camera, so it takes a perspective projection, whose w "
        "row is (0, 0, -1, 0) times a positive scale (clip w is the distance along the view "
        "axis)");
}

// Each axis' field of view, 2 atan(1 / |P[0][0]|) and 2 atan(1 / |P[1][1]|).
void checkFieldOfView(const glm::mat4& p) {
    for (int axis = 0; axis < 2; ++axis) {
        const double degrees =
            2.0 * std::atan(1.0 / std::fabs(double(p[axis][axis]))) * 180.0 / 3.14159265358979;
        // 1e-3 of slack: the matrix holds the engine's angle rounded to float.
        if (!(degrees >= limits::kMinFovDegrees * (1.0 - 1e-3) &&
              degrees <= limits::kMaxFovDegrees * (1.0 + 1e-6)))
            fail("camera.projection has a field of view of " + num(degrees) + " degrees " +
                 (axis == 0 ? "across (from P[0][0])" : "up and down (from P[1][1])") +
                 ": must be in " + rangeText(limits::kMinFovDegrees, limits::kMaxFovDegrees) +
                 " degrees, where single precision tells the pixels' rays apart and measured "
                 "results hold "
                 "(lightscatter.h, limits::kMinFovDegrees)");
    }
}

}  // namespace

ls::CameraParams setupCamera(const Camera& c) {
    ls::CameraParams out;
    out.view = matrix(c.view, "camera.view");
    out.projection = matrix(c.projection, "camera.projection");
    checkView(out.view);
    checkPerspective(out.projection);
    const DerivedPlanes d = derivePlanes(out.projection);
    const bool reversed = d.atDepth1 < d.atDepth0;
    const double nearD = reversed ? d.atDepth1 : d.atDepth0;
    const double farD = reversed ? d.atDepth0 : d.atDepth1;
    if (!(nearD > 0.0) || !std::isfinite(nearD) || !(farD > nearD))
        fail("camera.projection puts depth 0 at " + metres(d.atDepth0) + " and depth 1 at " +
             metres(d.atDepth1) +
             " along the view axis: it must map a range in front of the camera "
             "(view space looks down -Z) to depth [0, 1], as a Vulkan perspective projection does");
    checkFieldOfView(out.projection);
    // GLM's and OpenGL's projections put view-space up at clip-space up; Vulkan's clip y points
    // down the image. Taken as it is, such a projection mirrors every shaft top to bottom.
    if (out.projection[1][1] > 0.0f)
        fail("camera.projection maps view-space up to clip y up (P[1][1] = " +
             num(out.projection[1][1]) +
             " > 0): Vulkan's clip y points down the image, so the shafts would be mirrored; "
             "negate P[1][1] of a GLM or OpenGL projection (an engine that flips with a negative "
             "viewport height negates it for the plugin)");
    if (!(nearD >= limits::kMinNearPlane))
        fail("camera.projection puts the near plane at " + metres(nearD) + ": must be at least " +
             metres(limits::kMinNearPlane) +
             " (a reversed float32 depth buffer stores near / distance, which must stay a normal "
             "float; "
             "lightscatter.h, limits::kMinNearPlane)");
    if (std::isfinite(farD) && !(farD <= limits::kMaxLength * (1.0 + 1e-6)) && !c.infiniteFar)
        fail("camera.projection puts the far plane at " + metres(farD) + ": must be at most " +
             metres(limits::kMaxLength) + " (lightscatter.h, limits::kMaxLength)");
    if (c.reversedZ != reversed)
        fail(std::string("camera.reversedZ is ") + (c.reversedZ ? "true" : "false") +
             " but camera.projection puts the near plane at depth " + (reversed ? "1" : "0"));
    // float32 rounding of the matrix moves the far plane by about 2^-24 far/near relative; an
    // "infinite" projection nudged for precision is finite but far beyond anything it resolves.
    const bool derivedInfinite = !std::isfinite(farD);
    const double slack = 1e-3 + 1e-6 * (derivedInfinite ? 0.0 : farD / nearD);
    if (c.infiniteFar && !derivedInfinite && farD / nearD < 1e5)
        fail("camera.infiniteFar is true but camera.projection has a far plane at " + metres(farD));
    if (!c.infiniteFar && derivedInfinite)
        fail("camera.infiniteFar is false but camera.projection has no far plane (depth " +
             std::string(reversed ? "0" : "1") + " is at infinity" +
             (reversed
                  ? std::string(")")
                  : "; a float32 standard projection cannot hold a far plane more than about 2^24 "
                    "times its near plane, " +
                        metres(nearD) + ")"));
    auto agrees = [&](double given, double derived) {
        return std::fabs(given - derived) <= slack * derived;
    };
    if (c.nearPlane != 0.0f) {
        if (!(c.nearPlane > 0.0f) || !finite(c.nearPlane))
            fail("camera.nearPlane = " + num(c.nearPlane) +
                 ": must be > 0 (or 0: from the projection)");
        if (!agrees(c.nearPlane, nearD))
            fail("camera.nearPlane = " + num(c.nearPlane) +
                 " but camera.projection puts the near plane at " + metres(nearD) +
                 ": leave nearPlane 0 to take it from the projection");
    }
    if (!c.infiniteFar && c.farPlane != 0.0f) {
        if (!(c.farPlane > 0.0f) || !finite(c.farPlane))
            fail("camera.farPlane = " + num(c.farPlane) +
                 ": must be > 0 (or 0: from the projection)");
        if (!agrees(c.farPlane, farD))
            fail("camera.farPlane = " + num(c.farPlane) +
                 " but camera.projection puts the far plane at " + metres(farD) +
                 ": leave farPlane 0 to take it from the projection");
    }
    // Values the engine gave and that agree are kept as given; the others come from the matrix.
    out.nearPlane = c.nearPlane != 0.0f ? c.nearPlane : static_cast<float>(nearD);
    if (c.farPlane != 0.0f)
        out.farPlane = c.farPlane;
    else  // unused with an infinite far plane
        out.farPlane = c.infiniteFar ? std::numeric_limits<float>::max() : static_cast<float>(farD);
    out.reversedZ = reversed;
    out.infiniteFar = c.infiniteFar;
    return out;
}

void checkDepthResolution(const ls::CameraParams& camera, float maxDistance, VkFormat format) {
    const bool unorm16 = format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_D16_UNORM_S8_UINT;
    const bool floatDepth =
        format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D32_SFLOAT_S8_UINT;
    if (camera.reversedZ && floatDepth) return;  // near / distance: float32's exponent resolves it
    const double bits = unorm16 ? 16.0 : 24.0;
    const double ratio = std::pow(2.0, bits) / limits::kDepthStepsPerDistance;
    const double farthest = camera.infiniteFar ? double(maxDistance) : double(camera.farPlane);
    if (farthest <= ratio * camera.nearPlane) return;
    fail("camera.projection puts the near plane at " + metres(camera.nearPlane) + " and " +
         (camera.infiniteFar ? "the sky (medium.maxDistance) at " : "the far plane at ") +
         metres(farthest) + ": with " + (camera.reversedZ ? "reversed" : "standard") + " depth a " +
         rg::formatName(format) + " depth buffer steps by 2^-" + num(bits) +
         ", and the farthest distance may be at most " + num(ratio) +
         " times the near plane, where a step is 1/16 of the distance (beyond " +
         num(std::pow(2.0, bits)) + " times it reads as sky); move the near plane out to " +
         metres(farthest / ratio) + " or more" +
         (floatDepth ? ", or use reversed z"
                     : ", or use a D32_SFLOAT depth buffer with reversed z") +
         " (lightscatter.h, limits::kDepthStepsPerDistance)");
}

void checkViewProjection(const ls::CameraParams& camera) {
    // Scale-free: a near plane of 1e-29 m makes the determinant tiny, not the matrix singular.
    if (conditioning(camera.projection * camera.view) < 1e-9)
        fail("camera.projection * camera.view is singular");
    checkMatrixScale(camera.projection, "camera.projection");
}

}  // namespace lightscatter::detail
