#include "frame_setup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/type_ptr.hpp>
#include <string>

#include "rendergraph/format_info.h"

namespace lightscatter::detail {
namespace {

[[noreturn]] void fail(const std::string& message) { throw InvalidInput("lightscatter: " + message); }

std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

bool finite(float v) { return std::isfinite(v); }

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
        if (nonNegative && v[i] < 0.0f) fail(field + " = " + num(v[i]) + " in a channel: must be >= 0");
    }
    return {v[0], v[1], v[2]};
}

void checkImage(const ImageInput& img, const std::string& field, VkImageUsageFlags usage,
                const char* usageName) {
    if (!img.image) fail(field + ".image is VK_NULL_HANDLE");
    if (img.extent.width == 0 || img.extent.height == 0)
        fail(field + ".extent is " + std::to_string(img.extent.width) + "x" +
             std::to_string(img.extent.height) + ": must not be empty");
    if ((img.usage & usage) != usage)
        fail(field + ".usage lacks " + usageName + ", which the plugin needs to read or write it");
    if (img.finalLayout == VK_IMAGE_LAYOUT_UNDEFINED)
        fail(field + ".finalLayout is UNDEFINED: say which layout the image must be left in");
}

void checkDepthFormat(VkFormat f, const std::string& field) {
    if (!rg::hasDepth(f))
        fail(field + ".format " + rg::formatName(f) +
             " is not a depth format (D16_UNORM, X8_D24_UNORM_PACK32, D32_SFLOAT, or one of these "
             "with stencil)");
}

}  // namespace

void checkSettings(const Settings& s) {
    if (s.slices == 0 || s.slices % 4 != 0 || s.slices > 16384)
        fail("settings.slices = " + std::to_string(s.slices) +
             ": must be a positive multiple of 4 (a quarter per screen edge), at most 16384");
    if (s.samplesPerSlice < 2 || s.samplesPerSlice > 16384)
        fail("settings.samplesPerSlice = " + std::to_string(s.samplesPerSlice) +
             ": must be between 2 and 16384");
    const uint32_t st = s.initialSampleStep;
    if (st == 0 || (st & (st - 1)) != 0 || st > 128)
        fail("settings.initialSampleStep = " + std::to_string(st) +
             ": must be a power of two between 1 and 128");
    if (!(s.refinementThreshold > 0.0f) || !finite(s.refinementThreshold))
        fail("settings.refinementThreshold = " + num(s.refinementThreshold) + ": must be > 0");
    if (!(s.bilateralThreshold > 0.0f) || !finite(s.bilateralThreshold))
        fail("settings.bilateralThreshold = " + num(s.bilateralThreshold) + ": must be > 0");
    if (!finite(s.shadowDepthBias)) fail("settings.shadowDepthBias is not finite");
}

bool lightTouchesView(const ls::CameraParams& camera, const ls::LightParams& light) {
    if (light.kind != ls::LightKind::Spot || !(light.range < 1e29f)) return true;
    const glm::mat4 m = glm::transpose(camera.projection * camera.view);  // rows as columns
    glm::vec4 planes[6] = {m[3] + m[0], m[3] - m[0], m[3] + m[1], m[3] - m[1], m[2], m[3] - m[2]};
    const int count = camera.infiniteFar ? 5 : 6;
    const glm::vec3 axis = glm::normalize(light.direction);
    const float alpha = std::acos(std::clamp(light.cosHalfAngle, -1.0f, 1.0f));
    for (int i = 0; i < count; ++i) {
        const glm::vec3 n(planes[i]);
        const float len = glm::length(n);
        if (len < 1e-12f) continue;
        // The farthest reach of the range-capped cone along the plane's normal.
        const float angle = std::acos(std::clamp(glm::dot(n / len, axis), -1.0f, 1.0f));
        const float reach = angle <= alpha ? 1.0f : std::max(0.0f, std::cos(std::min(angle - alpha, 1.5707964f)));
        if ((glm::dot(n, light.position) + planes[i].w) / len + light.range * reach < 0.0f) return false;
    }
    return true;
}

FrameSetup setupFrame(const FrameDescription& f, bool withImages) {
    FrameSetup s;
    s.settings = f.profile == Profile::Custom ? f.custom : profileSettings(f.profile);
    if (f.profile != Profile::Custom) {
        // Profiles fix slices and samples; the finer choices are the engine's.
        s.settings.initialSampleStep = f.custom.initialSampleStep;
        s.settings.refinementThreshold = f.custom.refinementThreshold;
        s.settings.bilateralThreshold = f.custom.bilateralThreshold;
        s.settings.minMaxTrees = f.custom.minMaxTrees;
        s.settings.shadowFilter = f.custom.shadowFilter;
        s.settings.fixup = f.custom.fixup;
        s.settings.fixupMaxSteps = f.custom.fixupMaxSteps;
        s.settings.shadowDepthBias = f.custom.shadowDepthBias;
        s.settings.interpolation = f.custom.interpolation;
    }
    checkSettings(s.settings);

    // Camera.
    const Camera& c = f.camera;
    s.camera.view = matrix(c.view, "camera.view");
    s.camera.projection = matrix(c.projection, "camera.projection");
    if (!(c.nearPlane > 0.0f) || !finite(c.nearPlane))
        fail("camera.nearPlane = " + num(c.nearPlane) + ": must be > 0");
    if (!c.infiniteFar && (!(c.farPlane > c.nearPlane) || !finite(c.farPlane)))
        fail("camera.farPlane = " + num(c.farPlane) + ": must exceed nearPlane (" + num(c.nearPlane) +
             ") unless infiniteFar");
    if (std::fabs(glm::determinant(s.camera.projection * s.camera.view)) < 1e-30f)
        fail("camera.projection * camera.view is singular");
    s.camera.nearPlane = c.nearPlane;
    s.camera.farPlane = c.farPlane;
    s.camera.reversedZ = c.reversedZ;
    s.camera.infiniteFar = c.infiniteFar;

    // Light.
    const Light& l = f.light;
    s.light.kind = static_cast<ls::LightKind>(static_cast<int>(l.type));
    s.light.position = vec(l.position, "light.position", false);
    const glm::vec3 dir = vec(l.direction, "light.direction", false);
    if (glm::length(dir) < 1e-12f) fail("light.direction is the zero vector");
    s.light.direction = glm::normalize(dir);
    s.light.intensity = vec(l.intensity, "light.intensity", true);
    if (l.type == LightType::Spot &&
        (!(l.halfAngleDegrees > 0.0f) || !(l.halfAngleDegrees <= 89.0f)))
        fail("light.halfAngleDegrees = " + num(l.halfAngleDegrees) + ": must be in (0, 89]");
    s.light.cosHalfAngle = std::cos(l.halfAngleDegrees * 3.14159265f / 180.0f);
    if (!(l.range > 0.0f)) fail("light.range = " + num(l.range) + ": must be > 0");
    s.light.range = l.range;
    if (!(l.radius > 0.0f) || !finite(l.radius))
        fail("light.radius = " + num(l.radius) + ": must be > 0 (it keeps rays through the light finite)");
    s.light.radius = l.radius;
    s.light.shadowMapSize = l.shadowMapSize;
    s.light.shadowReversedZ = l.shadowReversedZ;
    if (l.type == LightType::Point && (l.shadowMapSize > 0 || f.shadowMap))
        fail("light.shadowMapSize / shadowMap: point lights are unshadowed (cube maps are not "
             "supported); remove the shadow map");
    if (l.shadowMapSize > 0) s.light.shadowViewProj = matrix(l.shadowViewProjection, "light.shadowViewProjection");

    // Medium.
    const Medium& m = f.medium;
    s.medium.betaR = vec(m.betaR, "medium.betaR", true);
    s.medium.betaM = vec(m.betaM, "medium.betaM", true);
    s.medium.sigmaA = vec(m.sigmaA, "medium.sigmaA", true);
    if (!(m.g > -1.0f && m.g < 1.0f)) fail("medium.g = " + num(m.g) + ": must be in (-1, 1)");
    s.medium.g = m.g;
    s.medium.isotropicMie = m.phase == MiePhase::Isotropic;
    if (!(m.maxDistance > 0.0f) || !finite(m.maxDistance))
        fail("medium.maxDistance = " + num(m.maxDistance) + ": must be > 0");
    s.medium.maxDistance = m.maxDistance;

    // Images.
    s.shadowed = l.shadowMapSize > 0;
    s.lightColor = f.lightColor.has_value();
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
                 std::to_string(f.depth.extent.width) + "x" + std::to_string(f.depth.extent.height));
        s.screen = f.depth.extent;
        if (s.shadowed != f.shadowMap.has_value())
            fail(s.shadowed ? "shadowMap is missing but light.shadowMapSize is " +
                                  std::to_string(l.shadowMapSize)
                            : "shadowMap is given but light.shadowMapSize is 0");
        if (f.shadowMap) {
            checkImage(*f.shadowMap, "shadowMap", VK_IMAGE_USAGE_SAMPLED_BIT, "SAMPLED");
            checkDepthFormat(f.shadowMap->format, "shadowMap");
            if (f.shadowMap->extent.width != l.shadowMapSize ||
                f.shadowMap->extent.height != l.shadowMapSize)
                fail("shadowMap.extent " + std::to_string(f.shadowMap->extent.width) + "x" +
                     std::to_string(f.shadowMap->extent.height) +
                     " does not match light.shadowMapSize " + std::to_string(l.shadowMapSize));
        }
        if (f.lightColor) checkImage(*f.lightColor, "lightColor", VK_IMAGE_USAGE_SAMPLED_BIT, "SAMPLED");
        if (f.inscatterOut) {
            checkImage(*f.inscatterOut, "inscatterOut", VK_IMAGE_USAGE_STORAGE_BIT, "STORAGE");
            if (f.inscatterOut->format != VK_FORMAT_R32G32B32A32_SFLOAT)
                fail("inscatterOut.format " + rg::formatName(f.inscatterOut->format) +
                     ": must be R32G32B32A32_SFLOAT");
            if (f.inscatterOut->extent.width != s.screen.width ||
                f.inscatterOut->extent.height != s.screen.height)
                fail("inscatterOut.extent differs from depth.extent");
        }
    }
    if (s.lightColor && !s.shadowed)
        fail("lightColor needs a shadow-mapped light: the color is looked up in the shadow map's space");

    s.epipolar.slices = s.settings.slices;
    s.epipolar.samples = s.settings.samplesPerSlice;
    s.epipolar.initialStep = s.settings.initialSampleStep;
    s.epipolar.refinementThreshold = s.settings.refinementThreshold;
    s.epipolar.bilateralThreshold = s.settings.bilateralThreshold;
    s.epipolar.minMaxTrees = s.settings.minMaxTrees && ls::treesFit(l.shadowMapSize);
    s.epipolar.bilinearShadow = s.settings.shadowFilter == ShadowFilter::Bilinear;
    s.epipolar.fixup = s.settings.fixup;
    s.epipolar.fixupMaxSteps = s.settings.fixupMaxSteps;
    s.epipolar.shadowDepthBias = s.settings.shadowDepthBias;
    s.epipolar.interpolateFraction = s.settings.interpolation == Interpolation::ShadowedFraction;
    return s;
}

}  // namespace lightscatter::detail
