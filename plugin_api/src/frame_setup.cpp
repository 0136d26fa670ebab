#include "frame_setup.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <string>

#include "rendergraph/format_info.h"

namespace lightscatter::detail {

namespace {

[[noreturn]] void fail(const std::string& message) {
    throw InvalidInput("lightscatter: " + message);
}

std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// A distance for a message: four figures (the planes read from a float32 matrix are not exact).
std::string metres(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4g m", v);
    return buf;
}

bool finite(float v) {
    return std::isfinite(v);
}

glm::mat4 matrix(const Mat4& m, const std::string& field) {
    for (size_t i = 0; i < 16; ++i)
        if (!finite(m[i]))
            fail(field + " element " + std::to_string(i) + " is " + num(m[i]) +
                 ": matrices must be finite");
    return glm::make_mat4(m.data());
}

glm::vec3 vec(const Vec3& v, const std::string& field, bool nonNegative) {
    for (size_t i = 0; i < 3; ++i) {
        if (!finite(v[i])) fail(field + " has a non-finite component (" + num(v[i]) + ")");
        if (nonNegative && v[i] < 0.0f)
            fail(field + " = " + num(v[i]) + " in a channel: must be >= 0");
    }
    return {v[0], v[1], v[2]};
}

// The bounds of lightscatter.h's limits, in the one message every range check gives.
std::string rangeText(double lo, double hi) {
    return "[" + num(lo) + ", " + num(hi) + "]";
}

float inRange(float v, const std::string& field, double lo, double hi, const std::string& why) {
    if (!(v >= lo && v <= hi))
        fail(field + " = " + num(v) + ": must be in " + rangeText(lo, hi) + " (" + why + ")");
    return v;
}

glm::vec3 vecInRange(const Vec3& v, const std::string& field, double lo, double hi,
                     const std::string& why) {
    for (size_t i = 0; i < 3; ++i)
        inRange(v[i], field + "[" + std::to_string(i) + "]", lo, hi, why);
    return {v[0], v[1], v[2]};
}

// A world -> clip matrix's scale: products with points within limits::kMaxLength must stay far
// from FLT_MAX, and its largest element far from the subnormals.
void checkMatrixScale(const glm::mat4& m, const std::string& field) {
    float largest = 0.0f;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) largest = std::max(largest, std::fabs(m[c][r]));
    if (!(largest >= 1e-20f && largest <= 1e20f))
        fail(field + " has its largest element at " + num(largest) +
             ": must be within [1e-20, 1e+20] (a clip matrix may be scaled freely: scale it)");
}

const char* layoutName(VkImageLayout l) {
    switch (l) {
        case VK_IMAGE_LAYOUT_UNDEFINED:
            return "UNDEFINED";
        case VK_IMAGE_LAYOUT_GENERAL:
            return "GENERAL";
        case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
            return "COLOR_ATTACHMENT_OPTIMAL";
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL:
            return "DEPTH_STENCIL_ATTACHMENT_OPTIMAL";
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL:
            return "DEPTH_STENCIL_READ_ONLY_OPTIMAL";
        case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
            return "SHADER_READ_ONLY_OPTIMAL";
        case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL:
            return "TRANSFER_SRC_OPTIMAL";
        case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
            return "TRANSFER_DST_OPTIMAL";
        case VK_IMAGE_LAYOUT_PREINITIALIZED:
            return "PREINITIALIZED";
        case VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL:
            return "DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL";
        case VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL:
            return "DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL";
        case VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL:
            return "DEPTH_ATTACHMENT_OPTIMAL";
        case VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL:
            return "DEPTH_READ_ONLY_OPTIMAL";
        case VK_IMAGE_LAYOUT_STENCIL_ATTACHMENT_OPTIMAL:
            return "STENCIL_ATTACHMENT_OPTIMAL";
        case VK_IMAGE_LAYOUT_STENCIL_READ_ONLY_OPTIMAL:
            return "STENCIL_READ_ONLY_OPTIMAL";
        case VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL:
            return "READ_ONLY_OPTIMAL";
        case VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL:
            return "ATTACHMENT_OPTIMAL";
        case VK_IMAGE_LAYOUT_PRESENT_SRC_KHR:
            return "PRESENT_SRC_KHR";
        default:
            return nullptr;
    }
}

// Why an image of this format and usage cannot be in `layout` (Vulkan's rules for the layouts of
// an image barrier), or empty when it can. `initial`: the layout the frame starts in; `read`: the
// plugin reads what the image holds.
std::string layoutProblem(VkImageLayout layout, VkFormat format, VkImageUsageFlags usage,
                          bool initial, bool read) {
    const bool depth = rg::hasDepth(format);
    const bool color = !rg::isDepthStencil(format);
    const VkImageUsageFlags attachment = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    const VkImageUsageFlags readable =
        VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT;
    auto needs = [&](VkImageUsageFlags any, const char* what) -> std::string {
        if (usage & any) return {};
        return std::string("needs an image created with ") + what + " usage";
    };
    switch (layout) {
        case VK_IMAGE_LAYOUT_UNDEFINED:
            if (!initial) return "is not a layout an image can be left in";
            if (read) return "discards what the image holds, and the plugin reads it";
            return {};
        case VK_IMAGE_LAYOUT_PREINITIALIZED:
            if (!initial) return "is not a layout an image can be left in";
            if (!color) return "is for linear color images written by the host";
            return {};
        case VK_IMAGE_LAYOUT_GENERAL:
            return {};
        case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
            if (!color) return "is a color layout, and the format is depth/stencil";
            return needs(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, "COLOR_ATTACHMENT");
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL:
            if (!depth) return "is a depth layout, and the format has no depth";
            return needs(attachment, "DEPTH_STENCIL_ATTACHMENT");
        case VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL:
            if (!depth) return "is a depth layout, and the format has no depth";
            return needs(attachment | readable,
                         "DEPTH_STENCIL_ATTACHMENT, SAMPLED or INPUT_ATTACHMENT");
        case VK_IMAGE_LAYOUT_STENCIL_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_STENCIL_READ_ONLY_OPTIMAL:
            return "is a layout of the stencil aspect alone, and the plugin uses color or depth";
        case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
            return needs(readable, "SAMPLED or INPUT_ATTACHMENT");
        case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL:
            return needs(VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "TRANSFER_SRC");
        case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
            return needs(VK_IMAGE_USAGE_TRANSFER_DST_BIT, "TRANSFER_DST");
        case VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL:
            return needs(attachment | readable,
                         "DEPTH_STENCIL_ATTACHMENT, SAMPLED or INPUT_ATTACHMENT");
        case VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL:
            return color ? needs(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, "COLOR_ATTACHMENT")
                         : needs(attachment, "DEPTH_STENCIL_ATTACHMENT");
        case VK_IMAGE_LAYOUT_PRESENT_SRC_KHR:
            if (!color) return "is a swapchain layout, and the format is depth/stencil";
            return {};
        default:
            return "is not a layout the plugin takes";
    }
}

void checkLayout(VkImageLayout layout, const ImageInput& img, const std::string& field,
                 bool initial, bool read) {
    const std::string why = layoutProblem(layout, img.format, img.usage, initial, read);
    if (why.empty()) return;
    const char* name = layoutName(layout);
    fail(field + " " +
         (name ? std::string(name) : "#" + std::to_string(static_cast<int64_t>(layout))) +
         " cannot hold this " + rg::formatName(img.format) + " image: the layout " + why);
}

// `volume`: a 3D image (volumeOut); the others are 2D, depth 1.
void checkImage(const ImageInput& img, const std::string& field, VkImageUsageFlags usage,
                const char* usageName, bool read = true, bool volume = false) {
    if (!img.image) fail(field + ".image is VK_NULL_HANDLE");
    if (img.extent.width == 0 || img.extent.height == 0 || (volume && img.depth == 0))
        fail(field + ".extent is " + std::to_string(img.extent.width) + "x" +
             std::to_string(img.extent.height) +
             (volume ? "x" + std::to_string(img.depth) : std::string()) + ": must not be empty");
    if (!volume && img.depth != 1)
        fail(field + ".depth = " + std::to_string(img.depth) +
             ": must be 1 (a 2D image; only volumeOut is a 3D one)");
    if ((img.usage & usage) != usage)
        fail(field + ".usage lacks " + usageName + ", which the plugin needs to read or write it");
    if (img.finalLayout == VK_IMAGE_LAYOUT_UNDEFINED)
        fail(field + ".finalLayout is UNDEFINED: say which layout the image must be left in");
    checkLayout(img.layout, img, field + ".layout", true, read);
    checkLayout(img.finalLayout, img, field + ".finalLayout", false, read);
}

void checkDepthFormat(VkFormat f, const std::string& field) {
    if (!rg::hasDepth(f))
        fail(field + ".format " + rg::formatName(f) +
             " is not a depth format (D16_UNORM, X8_D24_UNORM_PACK32, D32_SFLOAT, or one of these "
             "with stencil)");
}

// How far a matrix is from singular: |det| over the product of its rows' lengths (Hadamard's
// bound), 1 for orthogonal rows, 0 for a singular matrix; scale-free, so metres or kilometres do
// not matter.
double conditioning(const glm::dmat4& d) {
    double rows = 1.0;
    for (int r = 0; r < 4; ++r) rows *= glm::length(glm::dvec4(d[0][r], d[1][r], d[2][r], d[3][r]));
    if (!(rows > 0.0)) return 0.0;
    return std::fabs(glm::determinant(d)) / rows;
}

// The same about the point at the centre of the matrix's clip volume (a translation scales no
// direction): a light or camera a hundred kilometres from the origin has a large last column, not
// a singular matrix.
double conditioning(const glm::mat4& m) {
    const glm::dmat4 d(m);
    const double det = glm::determinant(d);
    if (!(std::fabs(det) > 0.0) || !std::isfinite(det)) return 0.0;
    const glm::dvec4 c = glm::inverse(d) * glm::dvec4(0.0, 0.0, 0.5, 1.0);
    if (!(std::fabs(c.w) > 0.0) || !std::isfinite(c.w)) return conditioning(d);
    glm::dmat4 centred(1.0);
    centred[3] = glm::dvec4(glm::dvec3(c) / c.w, 1.0);
    return conditioning(d * centred);
}

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

// Checks the camera against its projection and fills the planes the nodes use.
void setupCamera(const Camera& c, ls::CameraParams& out) {
    checkView(out.view);
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
}

// Standard depth, or a UNORM depth buffer either way round, steps by 2^-b (lightscatter.h,
// limits::kDepthStepsPerDistance): the farthest distance it must tell apart (the far plane, or with
// an infinite one the sky distance) may be at most 2^b / 16 times the near plane.
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

// A point light's cube face: Vulkan's cube layer order and face orientation (lightscatter.h,
// Light::cubeFaceViewProjections). For each face, the world axis it looks along and the world
// directions that land at clip x/w = +1 (sc) and y/w = +1 (tc).
struct CubeFace {
    const char* name;
    glm::dvec3 axis, sc, tc;
};
const CubeFace kCubeFaces[6] = {
    {"+X", {1, 0, 0}, {0, 0, -1}, {0, -1, 0}}, {"-X", {-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
    {"+Y", {0, 1, 0}, {1, 0, 0}, {0, 0, 1}},   {"-Y", {0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
    {"+Z", {0, 0, 1}, {1, 0, 0}, {0, -1, 0}},  {"-Z", {0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},
};

std::string ndcText(double x, double y) {
    return "(" + num(x) + ", " + num(y) + ")";
}

// Checks face `i`'s world -> clip matrix against the face it must be: its axis, its corners (a
// 90-degree square frustum with Vulkan's orientation) and its depth direction, at 1 m and 10 m
// from the light, to 1e-3 in clip x/w and y/w.
glm::mat4 checkCubeFace(const Mat4& given, size_t i, const glm::vec3& light, bool reversedZ,
                        const std::string& at) {
    const std::string field = at + ".cubeFaceViewProjections[" + std::to_string(i) + "]";
    const glm::mat4 m = matrix(given, field);
    const CubeFace& f = kCubeFaces[i];
    if (conditioning(m) < 1e-9)
        fail(field +
             " is singular (all zero?): a point light's shadow map needs each face's world -> clip "
             "matrix (face " +
             f.name + ")");
    checkMatrixScale(m, field);
    const glm::dmat4 d(m);
    const glm::dvec3 L(light);
    double depthAt[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
        const double dist = k == 0 ? 1.0 : 10.0;
        const struct { double u, v; } probes[4] = {{0, 0}, {1, 0}, {0, 1}, {-1, -1}};
        for (const auto& p : probes) {
            const glm::dvec3 dir = f.axis + p.u * f.sc + p.v * f.tc;
            const glm::dvec4 c = d * glm::dvec4(L + dist * dir, 1.0);
            if (!(c.w > 0.0))
                fail(field + " puts the point " + metres(dist) + " along " + f.name +
                     " from light.position behind its camera (clip w " + num(c.w) + "): face " +
                     std::to_string(i) + " must look along " + f.name + " from the light");
            const double x = c.x / c.w, y = c.y / c.w;
            if (std::fabs(x - p.u) > 1e-3 || std::fabs(y - p.v) > 1e-3) {
                if (p.u == 0 && p.v == 0)
                    fail(field + " does not look along " + f.name +
                         " from light.position: the axis " + metres(dist) + " out lands at clip " +
                         ndcText(x, y) + ", not the centre (face order +X, -X, +Y, -Y, +Z, -Z)");
                fail(field + " is not face " + f.name +
                     " as Vulkan samples a cube: a direction that must land at clip " +
                     ndcText(p.u, p.v) + " lands at " + ndcText(x, y) +
                     " (a 90-degree square frustum, oriented as lightscatter.h documents)");
            }
            if (p.u == 0 && p.v == 0) depthAt[k] = c.z / c.w;
        }
    }
    const bool decreasing = depthAt[1] < depthAt[0];
    if (depthAt[1] == depthAt[0] || decreasing != reversedZ)
        fail(field + " puts depth " + num(depthAt[0]) + " at 1 m and " + num(depthAt[1]) +
             " at 10 m from the light, but light.shadowReversedZ is " +
             (reversedZ ? "true" : "false") + ": depth must " +
             (reversedZ ? "decrease" : "increase") + " away from the light");
    return m;
}

}  // namespace

namespace {

void checkBox(const OccluderBox& b, const std::string& field) {
    const glm::vec3 c = vec(b.center, field + ".center", false);
    const glm::vec3 h = vec(b.halfExtents, field + ".halfExtents", false);
    for (int i = 0; i < 3; ++i) {
        if (!(h[i] > 0.0f))
            fail(field + ".halfExtents[" + std::to_string(i) + "] = " + num(h[i]) +
                 ": must be > 0");
        // The beam tree works in double, but its pyramids end on the shaders' float lengths.
        if (std::fabs(c[i]) > limits::kMaxLength || h[i] > limits::kMaxLength)
            fail(field + (std::fabs(c[i]) > limits::kMaxLength ? ".center[" : ".halfExtents[") +
                 std::to_string(i) +
                 "] = " + num(std::fabs(c[i]) > limits::kMaxLength ? c[i] : h[i]) +
                 ": must be within +-" + num(limits::kMaxLength) + " m (limits::kMaxLength)");
    }
    glm::vec3 a[3];
    for (int i = 0; i < 3; ++i) {
        a[i] =
            vec(b.axes[static_cast<size_t>(i)], field + ".axes[" + std::to_string(i) + "]", false);
        if (std::fabs(glm::length(a[i]) - 1.0f) > 1e-3f)
            fail(field + ".axes[" + std::to_string(i) + "] has length " + num(glm::length(a[i])) +
                 ": must be unit");
    }
    for (int i = 0; i < 3; ++i)
        if (std::fabs(glm::dot(a[i], a[(i + 1) % 3])) > 1e-3f)
            fail(field + ".axes[" + std::to_string(i) + "] and [" + std::to_string((i + 1) % 3) +
                 "] are not orthogonal (dot " + num(glm::dot(a[i], a[(i + 1) % 3])) + ")");
}

// Every corner of `inner` within `outer` (to a millimetre or 1e-4 of its size).
bool boxInside(const OccluderBox& inner, const OccluderBox& outer) {
    const glm::vec3 oc(outer.center[0], outer.center[1], outer.center[2]);
    const glm::vec3 ic(inner.center[0], inner.center[1], inner.center[2]);
    const glm::vec3 oh(outer.halfExtents[0], outer.halfExtents[1], outer.halfExtents[2]);
    const float tolerance = std::max(1e-3f, 1e-4f * glm::length(oh));
    for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 p = ic;
        for (int i = 0; i < 3; ++i) {
            const auto& ax = inner.axes[static_cast<size_t>(i)];
            const float s = (corner >> i & 1) ? 1.0f : -1.0f;
            p += s * inner.halfExtents[static_cast<size_t>(i)] * glm::vec3(ax[0], ax[1], ax[2]);
        }
        for (int i = 0; i < 3; ++i) {
            const auto& ax = outer.axes[static_cast<size_t>(i)];
            if (std::fabs(glm::dot(p - oc, glm::vec3(ax[0], ax[1], ax[2]))) > oh[i] + tolerance)
                return false;
        }
    }
    return true;
}

}  // namespace

std::vector<ls::beam::Occluder> beamOccluders(const std::vector<Occluder>& occluders) {
    checkOccluders(occluders);
    auto box = [](const OccluderBox& b) {
        ls::beam::OrientedBox o;
        o.center = {b.center[0], b.center[1], b.center[2]};
        for (int i = 0; i < 3; ++i) {
            const auto& a = b.axes[static_cast<size_t>(i)];
            o.axes[i] = glm::normalize(glm::dvec3(a[0], a[1], a[2]));
        }
        o.halfExtents = {b.halfExtents[0], b.halfExtents[1], b.halfExtents[2]};
        return o;
    };
    std::vector<ls::beam::Occluder> out;
    out.reserve(occluders.size());
    for (const Occluder& o : occluders) {
        ls::beam::Occluder b;
        b.outer = box(o.outer);
        if (o.inner) b.inner = box(*o.inner);
        out.push_back(b);
    }
    return out;
}

void checkOccluders(const std::vector<Occluder>& occluders) {
    if (occluders.size() > kMaxOccluders)
        fail("occluders has " + std::to_string(occluders.size()) + " entries: at most " +
             std::to_string(kMaxOccluders));
    for (size_t i = 0; i < occluders.size(); ++i) {
        const std::string field = "occluders[" + std::to_string(i) + "]";
        checkBox(occluders[i].outer, field + ".outer");
        if (!occluders[i].inner) continue;
        checkBox(*occluders[i].inner, field + ".inner");
        if (!boxInside(*occluders[i].inner, occluders[i].outer))
            fail(field + ".inner is not inside " + field +
                 ".outer: an inner box lies within the object, "
                 "and the outer box encloses it");
    }
}

void checkSettings(const Settings& s, const std::string& at) {
    const std::string c = at + ".";
    if (s.slices == 0 || s.slices % 4 != 0 || s.slices > 16384)
        fail(c + "slices = " + std::to_string(s.slices) +
             ": must be a positive multiple of 4 (a quarter per screen edge), at most 16384");
    if (s.samplesPerSlice < 2 || s.samplesPerSlice > 16384)
        fail(c + "samplesPerSlice = " + std::to_string(s.samplesPerSlice) +
             ": must be between 2 and 16384");
    const uint32_t st = s.initialSampleStep;
    if (st == 0 || (st & (st - 1)) != 0 || st > 128)
        fail(c + "initialSampleStep = " + std::to_string(st) +
             ": must be a power of two between 1 and 128");
    if (!(s.refinementThreshold > 0.0f) || !finite(s.refinementThreshold))
        fail(c + "refinementThreshold = " + num(s.refinementThreshold) + ": must be > 0");
    if (!(s.inscatterRefinementThreshold >= 0.0f) || !finite(s.inscatterRefinementThreshold))
        fail(c + "inscatterRefinementThreshold = " + num(s.inscatterRefinementThreshold) +
             ": must be finite and >= 0 (0: off)");
    if (!(s.bilateralThreshold > 0.0f) || !finite(s.bilateralThreshold))
        fail(c + "bilateralThreshold = " + num(s.bilateralThreshold) + ": must be > 0");
    inRange(s.shadowDepthBias, c + "shadowDepthBias", -1.0, 1.0,
            "the depth range: beyond it every ray is lit, or shadowed, all the same");
    if (s.coneSamples < 1 || s.coneSamples > 4096)
        fail(c + "coneSamples = " + std::to_string(s.coneSamples) + ": must be between 1 and 4096");
    if (s.froxelTile < 2 || s.froxelTile > 64)
        fail(c + "froxelTile = " + std::to_string(s.froxelTile) +
             ": must be between 2 and 64 pixels");
    if (s.froxelSlices < 4 || s.froxelSlices > 512)
        fail(c + "froxelSlices = " + std::to_string(s.froxelSlices) +
             ": must be between 4 and 512");
    inRange(s.froxelHistoryWeight, c + "froxelHistoryWeight", 0.0, 0.99,
            "the history's share of each froxel; 1 would never take a new frame");
    if (s.froxelFarDistance != 0.0f)
        inRange(s.froxelFarDistance, c + "froxelFarDistance", 1e-6, limits::kMaxLength,
                "or 0: the medium's maxDistance");
    if (s.planeCount < 2 || s.planeCount > 4096)
        fail(c + "planeCount = " + std::to_string(s.planeCount) + ": must be between 2 and 4096");
    if (s.planeSpacing != 0.0f)
        inRange(s.planeSpacing, c + "planeSpacing", 1e-6, limits::kMaxLength,
                "metres between sampling planes, or 0: planeCount planes");
    if (s.planeTarget != PlaneTarget::Float16 && s.planeTarget != PlaneTarget::Float32 &&
        s.planeTarget != PlaneTarget::Rgba8Channels)
        fail(c + "planeTarget is not a PlaneTarget value");
    if (s.planeRange != 0.0f)
        inRange(s.planeRange, c + "planeRange", 1e-30, 1e30,
                "or 0: automatic; the 8-bit target is scaled by 4 / planeRange");
    if (s.planeBlur > 8)
        fail(c + "planeBlur = " + std::to_string(s.planeBlur) + ": at most 8 pixels");
    inRange(s.planeAmbient, c + "planeAmbient", 0.0, limits::kMaxAmbient,
            "1/m^2, beside the inverse square; lightscatter.h, limits::kMaxAmbient");
    if (!(s.noiseAmplitude >= 0.0f && s.noiseAmplitude <= 1.0f))
        fail(c + "noiseAmplitude = " + num(s.noiseAmplitude) + ": must be in [0, 1]");
    inRange(s.noiseScale, c + "noiseScale", limits::kMinNoiseScale, limits::kMaxNoiseScale,
            "a tile's size; lightscatter.h, limits::kMinNoiseScale");
    for (size_t i = 0; i < s.noiseVelocity.size(); ++i)
        if (!finite(s.noiseVelocity[i]))
            fail(c + "noiseVelocity[" + std::to_string(i) + "] is not finite");
    if (s.lightModel != LightModel::Full && s.lightModel != LightModel::Simplified)
        fail(c + "lightModel is not a LightModel value");
    inRange(s.simplifiedA1, c + "simplifiedA1", limits::kMinSimplifiedA1, limits::kMaxSimplifiedA1,
            "seed 004's falloff I / (a1 r^2 + a0); lightscatter.h, limits::kMinSimplifiedA1");
    inRange(s.simplifiedA0, c + "simplifiedA0", 0.0, limits::kMaxSimplifiedA0,
            "m^2, seed 004's falloff I / (a1 r^2 + a0); lightscatter.h, limits::kMaxSimplifiedA0");
}

namespace {

void oneLayer(const ImageInput* img, const std::string& field) {
    if (img && img->arrayLayers != 1)
        fail(field + ".arrayLayers = " + std::to_string(img->arrayLayers) +
             ": must be 1 (only a point light's shadow map has layers: 6)");
}

}  // namespace

Settings mergedSettings(Profile profile, const Settings& custom) {
    // Everything is the engine's (custom) but what the profile decides: a field added to Settings
    // is the engine's without a word here.
    return profile == Profile::Custom ? custom : withProfileSizes(custom, profile);
}

FrameSetup setupFrameWide(const FrameDescription& f, bool withImages) {
    FrameSetup s;
    s.settings = mergedSettings(f.profile, f.custom);
    checkSettings(s.settings);
    // Checked, and converted, only for the methods that read them (beamOccluders): the others
    // ignore them, as the header says, and a scene of 100,000 parts must not stop them.
    s.occluders = f.occluders.size();
    if (!std::isfinite(f.timeSeconds))
        fail("timeSeconds = " + num(f.timeSeconds) + ": must be finite");
    s.timeSeconds = f.timeSeconds;
    if (!(f.preExposure >= 0.0f && f.preExposure <= limits::kMaxPreExposure))
        fail("preExposure = " + num(f.preExposure) + ": must be in [0, " +
             num(limits::kMaxPreExposure) + "] (lightscatter.h, limits::kMaxPreExposure)");
    s.preExposure = f.preExposure;

    // Camera.
    const Camera& c = f.camera;
    s.camera.view = matrix(c.view, "camera.view");
    s.camera.projection = matrix(c.projection, "camera.projection");
    setupCamera(c, s.camera);
    // What the depth buffer can resolve, before anything that a near plane too small for it
    // would break (the depth format is the engine's image's: unknown to the budget).
    if (withImages && rg::hasDepth(f.depth.format) && f.medium.maxDistance > 0.0f)
        checkDepthResolution(s.camera, f.medium.maxDistance, f.depth.format);
    // Scale-free: a near plane of 1e-29 m makes the determinant tiny, not the matrix singular.
    if (conditioning(s.camera.projection * s.camera.view) < 1e-9)
        fail("camera.projection * camera.view is singular");
    checkMatrixScale(s.camera.projection, "camera.projection");

    // Medium.
    const Medium& m = f.medium;
    const std::string perMetre = "1/m; lightscatter.h, limits::kMaxCoefficient";
    s.medium.betaR = vecInRange(m.betaR, "medium.betaR", 0.0, limits::kMaxCoefficient, perMetre);
    s.medium.betaM = vecInRange(m.betaM, "medium.betaM", 0.0, limits::kMaxCoefficient, perMetre);
    s.medium.sigmaA = vecInRange(m.sigmaA, "medium.sigmaA", 0.0, limits::kMaxCoefficient, perMetre);
    if (!(m.g > -1.0f && m.g < 1.0f)) fail("medium.g = " + num(m.g) + ": must be in (-1, 1)");
    s.medium.g = m.g;
    if (m.phase != MiePhase::CornetteShanks && m.phase != MiePhase::Isotropic &&
        m.phase != MiePhase::Hazy)
        fail("medium.phase is not a MiePhase value");
    s.medium.phase = m.phase;
    if (!(m.maxDistance > 0.0f && m.maxDistance <= limits::kMaxLength))
        fail("medium.maxDistance = " + num(m.maxDistance) + ": must be in (0, " +
             num(limits::kMaxLength) + "] (metres; lightscatter.h, limits::kMaxLength)");
    s.medium.maxDistance = m.maxDistance;

    // Images.
    s.engineNoise = f.noise.has_value();
    s.depthAttachment =
        !withImages || (f.depth.usage & VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT) != 0;
    s.inscatterOut = f.inscatterOut.has_value();
    if (withImages) {
        checkImage(f.depth, "depth", VK_IMAGE_USAGE_SAMPLED_BIT, "SAMPLED");
        checkDepthFormat(f.depth.format, "depth");
        checkImage(f.color, "color", VK_IMAGE_USAGE_STORAGE_BIT, "STORAGE");
        if (f.color.format != VK_FORMAT_R16G16B16A16_SFLOAT &&
            f.color.format != VK_FORMAT_R32G32B32A32_SFLOAT)
            fail("color.format " + rg::formatName(f.color.format) +
                 ": must be R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT (linear HDR)");
        if (f.color.extent.width != f.depth.extent.width ||
            f.color.extent.height != f.depth.extent.height)
            fail("color.extent " + std::to_string(f.color.extent.width) + "x" +
                 std::to_string(f.color.extent.height) + " differs from depth.extent " +
                 std::to_string(f.depth.extent.width) + "x" +
                 std::to_string(f.depth.extent.height));
        s.screen = f.depth.extent;
        oneLayer(&f.depth, "depth");
        oneLayer(&f.color, "color");
        oneLayer(f.noise ? &*f.noise : nullptr, "noise");
        oneLayer(f.inscatterOut ? &*f.inscatterOut : nullptr, "inscatterOut");
        if (f.noise) checkImage(*f.noise, "noise", VK_IMAGE_USAGE_SAMPLED_BIT, "SAMPLED");
        if (f.inscatterOut) {
            checkImage(*f.inscatterOut, "inscatterOut", VK_IMAGE_USAGE_STORAGE_BIT, "STORAGE",
                       false);
            if (f.inscatterOut->format != VK_FORMAT_R32G32B32A32_SFLOAT)
                fail("inscatterOut.format " + rg::formatName(f.inscatterOut->format) +
                     ": must be R32G32B32A32_SFLOAT");
            if (f.inscatterOut->extent.width != s.screen.width ||
                f.inscatterOut->extent.height != s.screen.height)
                fail("inscatterOut.extent differs from depth.extent");
        }
        if (f.volumeOut) {
            // Its extent is the froxel grid's, checked once the frame's method is known
            // (checkVolumeOut).
            oneLayer(&*f.volumeOut, "volumeOut");
            checkImage(*f.volumeOut, "volumeOut", VK_IMAGE_USAGE_STORAGE_BIT, "STORAGE", false,
                       true);
            if (f.volumeOut->format != VK_FORMAT_R16G16B16A16_SFLOAT)
                fail("volumeOut.format " + rg::formatName(f.volumeOut->format) +
                     ": must be R16G16B16A16_SFLOAT");
        }
    }
    return s;
}

void setupLight(FrameSetup& s, const LightInput& light, const LightPaths& at, bool withImages) {
    if (light.settings) {
        // The light's own settings, as if the frame's profile were Custom with them.
        s.settings = *light.settings;
        checkSettings(s.settings, at.settings);
    }
    // Light.
    const Light& l = light.light;
    s.light.kind = l.type;
    s.light.position = vecInRange(l.position, at.light + ".position", -limits::kMaxLength,
                                  limits::kMaxLength, "metres; lightscatter.h, limits::kMaxLength");
    const glm::vec3 dir = vec(l.direction, at.light + ".direction", false);
    // A float's square overflows from 1.8e19 and underflows below 1e-19: such lengths are
    // normalised in double (ordinary ones as they always were, to the bit).
    const glm::dvec3 dirD(dir);
    const double dirScale = std::max({std::fabs(dirD.x), std::fabs(dirD.y), std::fabs(dirD.z)});
    if (!(dirScale > 0.0)) fail(at.light + ".direction is the zero vector");
    const float dirLength = glm::length(dir);
    s.light.direction = std::isfinite(dirLength) && dirLength > 1e-12f
                            ? glm::normalize(dir)
                            : glm::vec3(glm::normalize(dirD / dirScale));
    s.light.intensity = vecInRange(l.intensity, at.light + ".intensity", 0.0, limits::kMaxIntensity,
                                   "W/m^2 or W/sr; lightscatter.h, limits::kMaxIntensity");
    if (l.type == LightType::Spot) {
        const char* why =
            "degrees; below it single precision cannot resolve the cone, at 90 the cone is no "
            "longer convex; lightscatter.h, limits::kMinConeAngleDegrees";
        inRange(l.outerConeAngleDegrees, at.light + ".outerConeAngleDegrees",
                limits::kMinConeAngleDegrees, 89.0, why);
        inRange(l.innerConeAngleDegrees, at.light + ".innerConeAngleDegrees",
                limits::kMinConeAngleDegrees, 89.0, why);
        if (l.innerConeAngleDegrees > l.outerConeAngleDegrees)
            fail(at.light + ".innerConeAngleDegrees = " + num(l.innerConeAngleDegrees) +
                 ": must be at most outerConeAngleDegrees (" + num(l.outerConeAngleDegrees) + ")");
    }
    s.light.cosOuter = std::cos(l.outerConeAngleDegrees * 3.14159265f / 180.0f);
    s.light.cosInner = l.innerConeAngleDegrees == l.outerConeAngleDegrees
                           ? s.light.cosOuter
                           : std::cos(l.innerConeAngleDegrees * 3.14159265f / 180.0f);
    if (!(l.range > 0.0f) || !finite(l.range))
        fail(at.light + ".range = " + num(l.range) + ": must be > 0 and finite (1e30: no range)");
    s.light.range = l.range;
    if (l.rangeFalloff != RangeFalloff::Cut && l.rangeFalloff != RangeFalloff::Window)
        fail(at.light + ".rangeFalloff is not a RangeFalloff value");
    s.light.windowedRange = l.rangeFalloff == RangeFalloff::Window;
    inRange(l.radius, at.light + ".radius", limits::kMinRadius, limits::kMaxLength,
            "metres; it keeps rays through the light finite, lightscatter.h, limits::kMinRadius");
    s.light.radius = l.radius;
    s.light.shadowMapSize = l.shadowMapSize;
    s.light.shadowReversedZ = l.shadowReversedZ;
    if (l.type == LightType::Point && l.shadowMapSize > 0) {
        for (size_t i = 0; i < 6; ++i)
            s.light.cubeFaceViewProj[i] = checkCubeFace(
                l.cubeFaceViewProjections[i], i, s.light.position, l.shadowReversedZ, at.light);
    } else if (l.shadowMapSize > 0 || (light.lightColor && l.type != LightType::Point)) {
        // A light color without a shadow map is projected with the same matrix (the host computes
        // it for such a spot or directional light too), so it is checked the same way.
        s.light.shadowViewProj = matrix(l.shadowViewProjection, at.light + ".shadowViewProjection");
        // An all-zero (default) or otherwise singular matrix puts every point at one texel and
        // depth: the light would silently vanish or light everything.
        if (conditioning(s.light.shadowViewProj) < 1e-9)
            fail(at.light + ".shadowViewProjection is singular (all zero?): " +
                 (l.shadowMapSize > 0
                      ? "with light.shadowMapSize " + std::to_string(l.shadowMapSize) +
                            " it must be the shadow map's world -> light clip matrix"
                      : "with " + at.lightColor +
                            " it must be the world -> light clip matrix the color is projected "
                            "with"));
        checkMatrixScale(s.light.shadowViewProj, at.light + ".shadowViewProjection");
    }

    // The light's images.
    s.shadowed = l.shadowMapSize > 0;
    s.lightColor = light.lightColor.has_value();
    if (withImages) {
        if (s.shadowed != light.shadowMap.has_value())
            fail(s.shadowed ? at.shadowMap + " is missing but " + at.light + ".shadowMapSize is " +
                                  std::to_string(l.shadowMapSize)
                            : at.shadowMap + " is given but " + at.light + ".shadowMapSize is 0");
        oneLayer(light.lightColor ? &*light.lightColor : nullptr, at.lightColor);
        if (light.shadowMap) {
            const ImageInput& map = *light.shadowMap;
            const uint32_t layers = l.type == LightType::Point ? 6 : 1;
            if (map.arrayLayers != layers)
                fail(at.shadowMap + ".arrayLayers = " + std::to_string(map.arrayLayers) +
                     ": must be " +
                     (layers == 6
                          ? std::string(
                                "6 for a point light (its cube faces +X, -X, +Y, -Y, +Z, -Z)")
                          : std::string("1 for a ") +
                                (l.type == LightType::Spot ? "spot" : "directional") +
                                " light (6 only for a point light's cube map)"));
            checkImage(map, at.shadowMap, VK_IMAGE_USAGE_SAMPLED_BIT, "SAMPLED");
            checkDepthFormat(map.format, at.shadowMap);
            if (map.extent.width != l.shadowMapSize || map.extent.height != l.shadowMapSize)
                fail(at.shadowMap + ".extent " + std::to_string(map.extent.width) + "x" +
                     std::to_string(map.extent.height) + " does not match " + at.light +
                     ".shadowMapSize " + std::to_string(l.shadowMapSize));
        }
        if (light.lightColor)
            checkImage(*light.lightColor, at.lightColor, VK_IMAGE_USAGE_SAMPLED_BIT, "SAMPLED");
    }
    // Without a shadow map the color is marched at its own resolution (a piece per texel row or
    // column crossed).
    if (light.lightColor)
        s.light.lightColorSize =
            std::max(light.lightColor->extent.width, light.lightColor->extent.height);
    if (s.lightColor && l.type == LightType::Point)
        fail(at.lightColor +
             " is not supported with a point light: a light-space color texture needs a "
             "spot or directional light's single projection (light.shadowViewProjection)");

    applySettings(s, s.settings, l.shadowMapSize);
}

FrameSetup setupFrame(const FrameDescription& f, bool withImages) {
    FrameSetup s = setupFrameWide(f, withImages);
    setupLight(s, LightInput{f.light, f.shadowMap, f.lightColor, std::nullopt}, LightPaths{},
               withImages);
    return s;
}

void applySettings(ls::LightSetup& s, const Settings& st, uint32_t shadowMapSize) {
    s.epipolar.slices = st.slices;
    s.epipolar.samples = st.samplesPerSlice;
    s.epipolar.initialStep = st.initialSampleStep;
    s.epipolar.refinementThreshold = st.refinementThreshold;
    s.epipolar.inscatterRefinementThreshold = st.inscatterRefinementThreshold;
    s.epipolar.bilateralThreshold = st.bilateralThreshold;
    s.epipolar.minMaxTrees = st.minMaxTrees && ls::treesFit(shadowMapSize);
    s.epipolar.bilinearShadow = st.shadowFilter == ShadowFilter::Bilinear;
    s.epipolar.fixup = st.fixup;
    s.epipolar.fixupMaxSteps = st.fixupMaxSteps;
    s.epipolar.interpolateFraction = st.interpolation == Interpolation::ShadowedFraction;
    s.planes.planes = st.planeCount;
    s.planes.spacing = st.planeSpacing;
    s.planes.planeScaling = st.planeScaling;
    s.planes.eightBitTarget = st.planeTarget == PlaneTarget::Rgba8Channels;
    s.planes.range = st.planeRange;
    s.planes.ambient = st.planeAmbient;
    s.planes.noiseAmplitude = st.noiseAmplitude;
    s.planes.noiseScale = st.noiseScale;
    s.planes.noiseVelocity = {st.noiseVelocity[0], st.noiseVelocity[1], st.noiseVelocity[2],
                              st.noiseVelocity[3]};
    s.planeTarget = st.planeTarget;
    s.planeBlur = st.planeBlur;
    s.planeDither = st.planeDither;
    s.cone = {st.coneSamples, st.coneLimited, st.coneJitter};
    s.froxels = {st.froxelTile, st.froxelSlices, st.froxelFarDistance, st.froxelTemporal,
                 st.froxelHistoryWeight};
    s.shadowSampling = st.shadowSampling;
    s.light.shadowDepthBias = st.shadowDepthBias;
    s.noise = st.noiseAmplitude > 0.0f;
    s.simplified = st.lightModel == LightModel::Simplified;
}

namespace {

bool defaultLight(const Light& l) {
    const Light d;
    return l.type == d.type && l.position == d.position && l.direction == d.direction &&
           l.intensity == d.intensity && l.innerConeAngleDegrees == d.innerConeAngleDegrees &&
           l.outerConeAngleDegrees == d.outerConeAngleDegrees && l.range == d.range &&
           l.rangeFalloff == d.rangeFalloff && l.radius == d.radius &&
           l.shadowViewProjection == d.shadowViewProjection &&
           l.cubeFaceViewProjections == d.cubeFaceViewProjections &&
           l.shadowMapSize == d.shadowMapSize && l.shadowReversedZ == d.shadowReversedZ;
}

}  // namespace

std::vector<FrameSetup> setupLights(const FrameDescription& frame, bool withImages) {
    std::string both;
    if (!defaultLight(frame.light)) both = "light";
    if (frame.shadowMap) both += both.empty() ? "shadowMap" : ", shadowMap";
    if (frame.lightColor) both += both.empty() ? "lightColor" : ", lightColor";
    if (!both.empty())
        fail("lights holds " + std::to_string(frame.lights.size()) + " lights and " + both +
             " is given too: give the single light (light, shadowMap, lightColor) or the list "
             "(lights), "
             "never both");
    if (frame.lights.size() > kMaxLights)
        fail("lights holds " + std::to_string(frame.lights.size()) + " lights: at most " +
             std::to_string(kMaxLights) +
             " (kMaxLights; each light is a chain of passes and a table of its own)");
    // The frame's own part once; whatever fails there is not about a light.
    const FrameSetup frameWide = setupFrameWide(frame, withImages);
    std::vector<FrameSetup> setups;
    setups.reserve(frame.lights.size());
    for (size_t i = 0; i < frame.lights.size(); ++i) {
        const std::string at = "lights[" + std::to_string(i) + "]";
        LightPaths paths{at + ".light", at + ".shadowMap", at + ".lightColor",
                         frame.lights[i].settings ? at + ".settings" : "custom"};
        FrameSetup s = frameWide;
        s.lightPath = paths.light;
        s.settingsPath = paths.settings;
        try {
            setupLight(s, frame.lights[i], paths, withImages);
        } catch (const InvalidInput& e) {
            throw aboutLight(e, i);
        }
        setups.push_back(std::move(s));
    }
    return setups;
}

}  // namespace lightscatter::detail

namespace lightscatter::detail {

InvalidInput aboutLight(const InvalidInput& e, size_t i) {
    const std::string lead = "lightscatter: ";
    std::string m = e.what();
    if (m.rfind(lead, 0) == 0) m = m.substr(lead.size());
    return InvalidInput(lead + "lights[" + std::to_string(i) + "]: " + m);
}

std::vector<LightInput> lightInputs(const FrameDescription& frame) {
    if (!frame.lights.empty()) return frame.lights;
    return {LightInput{frame.light, frame.shadowMap, frame.lightColor, std::nullopt}};
}

ValidatedFrame validateFrame(const FrameDescription& frame, bool withImages) {
    ValidatedFrame v;
    v.list = !frame.lights.empty();
    if (v.list) {
        v.lights = setupLights(frame, withImages);
    } else {
        v.lights.push_back(setupFrame(frame, withImages));
    }
    for (FrameSetup& s : v.lights) {
        v.touchesView.push_back(ls::lightTouchesView(s.camera, s.light, s.medium));
        s.screenRect = ls::lightScreenRect(s.camera, s.light, s.medium, s.screen);
    }
    return v;
}

}  // namespace lightscatter::detail
