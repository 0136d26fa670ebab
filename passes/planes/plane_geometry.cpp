#include "plane_geometry.h"

#include "shared/spot_basis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
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
        const auto [r, u] = acrossAxis(a);
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

// How far from the camera the light's volume is built out to: past the farthest view ray's end.
double volumeReach(const CameraParams& camera, const LightParams& light,
                   const MediumParams& medium) {
    const float zFar = std::max(farthestViewDepth(camera, medium), camera.nearPlane * 1.001f);
    const glm::vec2 t = frustumTangents(camera);
    const glm::vec3 cameraPos = glm::vec3(glm::inverse(glm::dmat4(camera.view))[3]);
    return static_cast<double>(glm::length(light.position - cameraPos) +
                               zFar * std::sqrt(1.0f + t.x * t.x + t.y * t.y));
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

std::vector<glm::vec2> spotSlabFootprint(const CameraParams& camera, const LightParams& light,
                                         const MediumParams& medium, float front, float back,
                                         float depth) {
    if (light.kind != LightType::Spot || !(front < back) || !(depth > 0.0f)) return {};
    // The cone within its range held by a pyramid of kSides faces around it (apex first), in view
    // space: tighter than the square pyramid of the planes' box, whose corners reach 41% wider.
    constexpr int kSides = 8;
    const glm::dmat4 view(camera.view);
    const glm::dvec3 axis = glm::normalize(glm::dvec3(light.direction));
    const auto [r, u] = acrossAxis(axis);
    const double cosA = light.cosOuter;
    const double radius = std::sqrt(std::max(1.0 - cosA * cosA, 0.0)) / cosA /
                          std::cos(std::numbers::pi / kSides);  // per unit of depth
    const double reach =
        std::min(static_cast<double>(light.range), volumeReach(camera, light, medium));
    std::vector<glm::dvec3> v{glm::dvec3(view * glm::dvec4(glm::dvec3(light.position), 1.0))};
    for (int k = 0; k < kSides; ++k) {
        const double phi = 2.0 * std::numbers::pi * static_cast<double>(k) / kSides;
        const glm::dvec3 w = glm::dvec3(light.position) +
                             reach * (axis + radius * (std::cos(phi) * r + std::sin(phi) * u));
        v.emplace_back(view * glm::dvec4(w, 1.0));
    }
    // The pyramid cut to the slab is convex: its corners are the pyramid's own within the slab and
    // where its edges (from the apex, and around the base) cross the slab's two faces.
    const double d0 = front, d1 = back;
    std::vector<glm::dvec3> corners;
    for (const glm::dvec3& p : v)
        if (-p.z >= d0 && -p.z <= d1) corners.push_back(p);
    for (int k = 1; k <= kSides; ++k)
        for (const auto& [i, j] : {std::pair{0, k}, {k, k % kSides + 1}}) {
            const glm::dvec3 &p = v[i], &q = v[j];
            for (double d : {d0, d1})
                if ((-p.z - d) * (-q.z - d) < 0.0)
                    corners.push_back(p + (q - p) * ((d + p.z) / (p.z - q.z)));
        }
    if (corners.empty()) return {};
    // Each corner carried along its view ray to the plane; a corner at the camera lands at
    // infinity, and then the view's whole rectangle stands for the hull.
    const glm::dvec2 half = glm::dvec2(frustumTangents(camera)) * (1.01 * double(depth));
    std::vector<glm::dvec2> q;
    for (const glm::dvec3& p : corners) {
        if (-p.z < 1e-6 * double(depth)) {
            q = {-half, {half.x, -half.y}, half, {-half.x, half.y}};
            break;
        }
        q.push_back(glm::dvec2(p) * (double(depth) / -p.z));
    }
    // Their convex hull (monotone chain, counter-clockwise), then cut to the view's rectangle.
    std::sort(q.begin(), q.end(), [](const glm::dvec2& a, const glm::dvec2& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::dvec2> hull(2 * q.size());
    size_t k = 0;
    for (size_t i = 0; i < q.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], q[i]) <= 0.0) --k;
        hull[k++] = q[i];
    }
    for (size_t i = q.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(hull[k - 2], hull[k - 1], q[i]) <= 0.0) --k;
        hull[k++] = q[i];
    }
    hull.resize(k > 1 ? k - 1 : k);
    for (int dim = 0; dim < 2; ++dim)
        for (double side : {-1.0, 1.0}) {
            const double limit = side * half[dim];
            auto in = [&](const glm::dvec2& p) { return side * (p[dim] - limit) <= 0.0; };
            std::vector<glm::dvec2> cut;
            for (size_t i = 0; i < hull.size(); ++i) {
                const glm::dvec2 &a = hull[i], &b = hull[(i + 1) % hull.size()];
                if (in(a)) cut.push_back(a);
                if (in(a) != in(b))
                    cut.push_back(a + (b - a) * ((limit - a[dim]) / (b[dim] - a[dim])));
            }
            hull = std::move(cut);
        }
    if (hull.size() < 3) return {};
    return std::vector<glm::vec2>(hull.begin(), hull.end());
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
        glm::vec3 llo(1e30f), lhi(-1e30f);
        for (const glm::dvec3& w :
             lightVolumeCorners(light, static_cast<float>(volumeReach(camera, light, medium)))) {
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
