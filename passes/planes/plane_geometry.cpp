#include "plane_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace ls {
namespace {

constexpr float kPi = 3.14159265358979f;
const glm::vec3 kLuminance{0.2126f, 0.7152f, 0.0722f};

// The camera's half-extent tangents from the projection (Vulkan: y down, perspective).
glm::vec2 frustumTangents(const CameraParams& camera) {
    return {1.0f / std::fabs(camera.projection[0][0]), 1.0f / std::fabs(camera.projection[1][1])};
}

// How far a view ray can reach along the view axis: the far plane, or the sky distance.
float farthestViewDepth(const CameraParams& camera, const MediumParams& medium) {
    return camera.infiniteFar ? medium.maxDistance : std::min(camera.farPlane, medium.maxDistance);
}

// Corners of the part of the view frustum between view depths zNear and zFar (positive).
std::vector<glm::vec3> viewFrustumCorners(const CameraParams& camera, float zNear, float zFar) {
    const glm::vec2 t = frustumTangents(camera);
    std::vector<glm::vec3> c;
    for (float z : {zNear, zFar})
        for (float sx : {-1.0f, 1.0f})
            for (float sy : {-1.0f, 1.0f}) c.emplace_back(sx * t.x * z, sy * t.y * z, -z);
    return c;
}

// World-space corners of the light's volume: a spot's pyramid (apex and far face, with the range
// or, when unbounded, the reach of the view as its depth), or the shadow map's box. In double: far
// from the origin a float corner is off by its last bit (6 cm at 1e6 m), and a box placed that
// far off missed part of a shaft (issue #42).
std::vector<glm::dvec3> lightVolumeCorners(const LightParams& light, float reach) {
    std::vector<glm::dvec3> c;
    if (light.kind == LightType::Spot) {
        const glm::dvec3 a = light.direction;
        const glm::dvec3 helper = std::fabs(a.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
        const glm::dvec3 r = glm::normalize(glm::cross(a, helper)), u = glm::cross(r, a);
        const double cosA = light.cosOuter;
        const double tanA = std::sqrt(std::max(1.0 - cosA * cosA, 0.0)) / cosA;
        const double depth = std::min(light.range, reach);
        const glm::dvec3 apex = light.position;
        c.push_back(apex);
        for (double sx : {-1.0, 1.0})
            for (double sy : {-1.0, 1.0})
                c.push_back(apex + depth * (a + tanA * (sx * r + sy * u)));
        return c;
    }
    const glm::dmat4 inv = glm::inverse(glm::dmat4(light.shadowViewProj));
    for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0})
            for (double z : {0.0, 1.0}) {
                const glm::dvec4 p = inv * glm::dvec4(x, y, z, 1.0);
                c.emplace_back(glm::dvec3(p) / p.w);
            }
    return c;
}

// betaR pR + betaM pM at one scattering angle, as shaders/shared/math.glsl's phaseSum.
glm::vec3 phaseSum(const MediumParams& m, float c) {
    const float rayleigh = 3.0f / (16.0f * kPi) * (1.0f + c * c);
    const float g = m.g, g2 = g * g;
    const float denom = std::max(1.0f + g2 - 2.0f * g * c, 1e-6f);
    const float h = 0.5f * (1.0f + c), h2 = h * h, h4 = h2 * h2;
    const float mie = m.phase == MiePhase::Hazy ? (1.0f + 9.0f * h4 * h4) / (8.0f * kPi)
                      : m.phase == MiePhase::Isotropic
                          ? 1.0f / (4.0f * kPi)
                          : 1.0f / (4.0f * kPi) * 3.0f * (1.0f - g2) / (2.0f * (2.0f + g2)) *
                                (1.0f + c * c) / (denom * std::sqrt(denom));
    return m.betaR * rayleigh + m.betaM * mie;
}

}  // namespace

float estimatedPlaneRange(const CameraParams& camera, const LightParams& light,
                          const MediumParams& medium, float front, float back) {
    const glm::mat4 toWorld = glm::inverse(camera.view);
    const glm::vec3 C = glm::vec3(toWorld[3]);
    const glm::vec2 t = frustumTangents(camera);
    const glm::vec3 betaT = medium.betaT();
    const float cosCone = light.cosOuter;
    // Rays on a grid over the screen (not the one through a point light: unshadowed, its peak is
    // 1/r0^2, which no shadowed scene shows, and the range would swallow everything else).
    std::vector<glm::vec3> rays;  // view space
    for (int y = 0; y <= 8; ++y)
        for (int x = 0; x <= 8; ++x)
            rays.emplace_back((static_cast<float>(x) / 4.0f - 1.0f) * t.x,
                              (static_cast<float>(y) / 4.0f - 1.0f) * t.y, -1.0f);
    constexpr int kSteps = 256;
    float peak = 0.0f;
    for (const glm::vec3& r : rays) {
        const glm::vec3 v = glm::normalize(glm::vec3(toWorld * glm::vec4(r, 0.0f)));
        const float c = 1.0f / glm::length(r);  // cos of the ray's angle to the view axis
        const float s0 = front / c, s1 = back / c, ds = (s1 - s0) / kSteps;
        glm::vec3 lin(0.0f);
        for (int k = 0; k < kSteps; ++k) {
            const float s = s0 + (static_cast<float>(k) + 0.5f) * ds;
            const glm::vec3 P = C + s * v;
            glm::vec3 irr = light.intensity;
            float cosTheta = glm::dot(v, -light.direction);
            if (light.kind != LightType::Directional) {
                const glm::vec3 d = light.position - P;
                const float dist = glm::length(d);
                if (light.kind == LightType::Spot &&
                    (glm::dot(-d, light.direction) < cosCone * dist || dist > light.range))
                    continue;
                cosTheta = dist > 0.0f ? glm::dot(v, d / dist) : 0.0f;
                irr *= glm::exp(-betaT * dist) / (dist * dist + light.radius * light.radius);
            }
            lin += glm::exp(-betaT * s) * phaseSum(medium, cosTheta) * irr * ds;
        }
        peak = std::max(peak, glm::dot(lin, kLuminance));
    }
    return std::max(1.25f * peak, 1e-30f);
}

std::string planesNote(uint32_t planes, float spacing) {
    if (planes == 0) return "no sampling plane (the light's volume is out of view)";
    char buf[96];
    std::snprintf(buf, sizeof buf, "%u sampling planes %.3g m apart", planes, spacing);
    return buf;
}

PlaneSettings planeSettings(const lightscatter::Settings& s) {
    PlaneSettings p;
    p.planes = s.planes.count;
    p.spacing = s.planes.spacing;
    p.planeScaling = s.planes.scaling;
    p.eightBitTarget = s.planes.target == PlaneTarget::Rgba8Channels;
    p.range = s.planes.range;
    p.ambient = s.planes.ambient;
    p.noiseAmplitude = s.noiseAmplitude;
    p.noiseScale = s.noiseScale;
    p.noiseVelocity = {s.noiseVelocity[0], s.noiseVelocity[1], s.noiseVelocity[2],
                       s.noiseVelocity[3]};
    return p;
}

PlanePlacement placePlanes(const CameraParams& camera, const LightParams& light,
                           const MediumParams& medium, const PlaneSettings& settings, double time) {
    PlanePlacement out;
    const float zNear = camera.nearPlane;
    const float zFar = std::max(farthestViewDepth(camera, medium), zNear * 1.001f);
    const glm::vec2 tangents = frustumTangents(camera);
    const float reach = zFar * std::sqrt(1.0f + tangents.x * tangents.x + tangents.y * tangents.y);

    // The box in view space: the light's volume where it has one, always cut by the view frustum.
    const std::vector<glm::vec3> frustum = viewFrustumCorners(camera, zNear, zFar);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : frustum) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const bool bounded = light.kind == LightType::Spot ||
                         (light.kind == LightType::Directional && light.shadowMapSize > 0);
    float boxFront = zNear, boxBack = zFar;  // view depths (positive) the planes span
    if (bounded) {
        const glm::dmat4 view(camera.view);
        const glm::vec3 cameraPos = glm::vec3(glm::inverse(view)[3]);
        glm::vec3 llo(1e30f), lhi(-1e30f);
        for (const glm::dvec3& w :
             lightVolumeCorners(light, glm::length(light.position - cameraPos) + reach)) {
            const glm::vec3 p = glm::vec3(view * glm::dvec4(w, 1.0));
            llo = glm::min(llo, p);
            lhi = glm::max(lhi, p);
        }
        boxFront = std::max(zNear, -lhi.z);
        boxBack = std::min(zFar, -llo.z);
        if (light.kind == LightType::Spot) {  // a directional light lights outside its box too
            lo = glm::max(lo, llo);
            hi = glm::min(hi, lhi);
        }
    }
    if (!(boxFront < boxBack) || lo.x >= hi.x || lo.y >= hi.y) return out;

    uint32_t planes = settings.planes;
    if (settings.spacing > 0.0f) {
        // Seed 004's dz: as many planes as the depth extent needs at that spacing (in double: an
        // extent of kilometres over a spacing of micrometres is no float).
        const double n = std::ceil(double(boxBack - boxFront) / double(settings.spacing));
        planes = static_cast<uint32_t>(std::clamp(n, 2.0, 4096.0));
    } else if (settings.planeScaling) {
        // Seed 002 draws fewer planes as the viewer moves away from the light's volume: its depth
        // extent over its distance, down to an eighth.
        const float fraction =
            std::clamp((boxBack - boxFront) / std::max(boxFront, zNear), 0.125f, 1.0f);
        planes =
            std::max(2u, static_cast<uint32_t>(std::ceil(static_cast<float>(planes) * fraction)));
    }
    const float spacing = (boxBack - boxFront) / static_cast<float>(planes);
    // The estimate marches 81 rays on the CPU: only the 8-bit target reads the range.
    const float range = !settings.eightBitTarget ? 1.0f
                        : settings.range > 0.0f
                            ? settings.range
                            : estimatedPlaneRange(camera, light, medium, boxFront, boxBack);

    PlanePush& p = out.push;
    p.viewToWorld = glm::inverse(camera.view);
    p.boxMin = {lo.x, lo.y, boxFront, spacing};
    p.boxMax = {hi.x, hi.y, static_cast<float>(planes), 4.0f / range};  // a channel holds range / 4
    // The texture repeats: keep the offsets within a tile. In double, so that any finite time
    // and velocity give one (a float product overflows to inf, and inf - floor(inf) is NaN).
    for (int i = 0; i < 4; ++i) {
        const double scroll = double(settings.noiseVelocity[i]) * time;
        p.noise[i] = std::isfinite(scroll) ? static_cast<float>(scroll - std::floor(scroll)) : 0.0f;
    }
    p.params = {settings.ambient, settings.noiseAmplitude, 1.0f / settings.noiseScale,
                medium.maxDistance};

    // The 8-bit channels hold luminance; the medium and the light give it its color.
    const glm::vec3 color = (medium.betaR + medium.betaM) * light.intensity;
    const float luminance = glm::dot(color, kLuminance);
    out.resolve.tint =
        glm::vec4(luminance > 0.0f ? color / luminance * (range / 4.0f) : glm::vec3(0.0f), 0.0f);
    out.resolve.slab = {boxFront, boxBack, 0.0f, 0.0f};
    out.planes = planes;
    return out;
}

}  // namespace ls
