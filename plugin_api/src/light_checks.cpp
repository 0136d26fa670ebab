#include "light_checks.h"

#include <algorithm>
#include <cmath>

#include "cube_face_checks.h"
#include "enum_checks.h"
#include "field_checks.h"
#include "image_checks.h"
#include "light_projection_checks.h"
#include "matrix_checks.h"

namespace lightscatter::detail {

void setupLight(ls::LightSetup& s, const LightInput& light, const LightPaths& at, bool withImages) {
    if (light.settings) {
        // The light's own settings, as if the frame's profile were Custom with them.
        s.settings = *light.settings;
        checkSettings(s.settings, at.settings);
    }
    // Light.
    const Light& l = light.light;
    checkLightType(l.type, at.light + ".type");
    s.light.kind = l.type;
    s.light.position = vecInRange(l.position, at.light + ".position", -limits::kMaxLength,
                                  limits::kMaxLength, "metres; lightscatter.h, limits::kMaxLength");
    const glm::vec3 dir = vec(l.direction, at.light + ".direction");
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
    checkRangeFalloff(l.rangeFalloff, at.light + ".rangeFalloff");
    s.light.windowedRange = l.rangeFalloff == RangeFalloff::Window;
    inRange(l.radius, at.light + ".radius", limits::kMinRadius, limits::kMaxLength,
            "metres; it keeps rays through the light finite, lightscatter.h, limits::kMinRadius");
    s.light.radius = l.radius;
    s.light.shadowMapSize = l.shadowMapSize;
    s.light.shadowReversedZ = l.shadowReversedZ;
    s.light.shadowDepthBias = s.settings.shadowDepthBias;
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
            fail(at.light + ".shadowViewProjection is singular" +
                 (allZero(l.shadowViewProjection) ? " (all zero)" : "") + ": " +
                 (l.shadowMapSize > 0
                      ? "with " + at.light + ".shadowMapSize " + std::to_string(l.shadowMapSize) +
                            " it must be the shadow map's world -> light clip matrix"
                      : "with " + at.lightColor +
                            " it must be the world -> light clip matrix the color is projected "
                            "with"));
        checkMatrixScale(s.light.shadowViewProj, at.light + ".shadowViewProjection");
        // Where the matrix is used, it must be this light's: its apex, axis and frustum.
        ProjectedLight projected;
        projected.type = l.type;
        projected.position = glm::dvec3(s.light.position);
        projected.direction = glm::normalize(glm::dvec3(s.light.direction));
        projected.outerConeAngleDegrees = l.outerConeAngleDegrees;
        projected.range = l.range;
        projected.shadowed = l.shadowMapSize > 0;
        projected.shadowReversedZ = l.shadowReversedZ;
        checkLightProjection(s.light.shadowViewProj, projected, at.light);
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
            checkImage(map, at.shadowMap, VK_IMAGE_USAGE_SAMPLED_BIT);
            checkDepthFormat(map.format, at.shadowMap);
            if (map.extent.width != l.shadowMapSize || map.extent.height != l.shadowMapSize)
                fail(at.shadowMap + ".extent " + std::to_string(map.extent.width) + "x" +
                     std::to_string(map.extent.height) + " does not match " + at.light +
                     ".shadowMapSize " + std::to_string(l.shadowMapSize));
        }
        if (light.lightColor)
            checkImage(*light.lightColor, at.lightColor, VK_IMAGE_USAGE_SAMPLED_BIT);
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
}

}  // namespace lightscatter::detail
