#include "light_projection_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "field_checks.h"

namespace lightscatter::detail {
namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

glm::dvec4 row(const glm::dmat4& m, int r) {
    return {m[0][r], m[1][r], m[2][r], m[3][r]};
}

std::string vecText(const glm::dvec3& v) {
    return "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")";
}

// atan2 rather than acos: acos loses the small angles the tolerances are made of.
double degreesBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * kDegreesPerRadian;
}

// How far from the spot the tolerance on its apex is measured: the nearer of its range and its
// shadow frustum's far plane (1000 times the near plane for a frustum with none), the distances at
// which a misplaced apex shows.
struct Reach {
    double metres = 0.0;
    std::string what;
};

Reach reachOf(const glm::dmat4& m, const glm::dvec3& apex, const glm::dvec3& axis, double range) {
    const glm::dvec4 z = row(m, 2), w = row(m, 3);
    // Along the axis, clip w = s t and clip z = z0 + c t at t metres from the apex.
    const double s = glm::dot(glm::dvec3(w), axis), c = glm::dot(glm::dvec3(z), axis);
    const double z0 = glm::dot(z, glm::dvec4(apex, 1.0));
    const double inf = std::numeric_limits<double>::infinity();
    auto distanceAtDepth = [&](double depth) {
        const double t = z0 / (depth * s - c);
        return std::isfinite(t) && t > 0.0 ? t : inf;
    };
    const double a = distanceAtDepth(0.0), b = distanceAtDepth(1.0);
    const double nearD = std::min(a, b), farD = std::max(a, b);
    Reach r{limits::kMaxLength, "limits::kMaxLength: its frustum has no planes"};
    if (std::isfinite(farD))
        r = {farD, "its shadow frustum's far plane"};
    else if (std::isfinite(nearD))
        r = {1e3 * nearD, "1000 times its shadow frustum's near plane, as it has no far plane"};
    if (range < r.metres) r = {range, "its range"};
    return r;
}

void checkSpot(const glm::dmat4& m, const ProjectedLight& l, const std::string& at) {
    const std::string matrix = at + ".shadowViewProjection";
    const glm::dvec4 x = row(m, 0), y = row(m, 1), w = row(m, 3);
    const glm::dvec3 x3(x), y3(y), w3(w);
    // The apex: the point every clip-space direction starts from, where x = y = w = 0.
    const glm::dmat3 rows = glm::transpose(glm::dmat3(x3, y3, w3));
    const double scale = glm::length(x3) * glm::length(y3) * glm::length(w3);
    if (!(scale > 0.0) || !(std::fabs(glm::determinant(rows)) > 1e-9 * scale))
        fail(matrix +
             (glm::length(w3) == 0.0
                  ? std::string(" is orthographic (its clip w is the same at every point)")
                  : std::string(" maps no single point to clip x = y = w = 0 (it has no apex)")) +
             ": a spot's shadow map is a perspective projection from " + at + ".position");
    const glm::dvec3 apex = glm::inverse(rows) * -glm::dvec3(x.w, y.w, w.w);
    // The axis: from the apex to the centre of clip space (x = y = 0), in front of it (w > 0).
    glm::dvec3 axis = glm::normalize(glm::cross(x3, y3));
    if (glm::dot(w3, axis) < 0.0) axis = -axis;

    const Reach reach = reachOf(m, apex, axis, l.range);
    const double offset = glm::length(apex - l.position);
    const double tolerance =
        kApexOfReach * reach.metres + kApexFromOrigin * glm::length(l.position);
    if (!(offset <= tolerance))
        fail(at + ".position is " + metres(offset) + " from the apex of " + matrix + ", " +
             vecText(apex) + " (the point it maps to clip x = y = w = 0): must be within " +
             metres(tolerance) + " (1e-3 of the light's reach, " + metres(reach.metres) + ", " +
             reach.what +
             ", plus 1e-5 of its distance from the origin): a spot's shadow map is seen from its "
             "position");

    const double off = degreesBetween(axis, l.direction);
    if (!(off <= kAxisDegrees))
        fail(at + ".direction is " + num(off) + " degrees off the axis of " + matrix + ", " +
             vecText(axis) +
             " (from its apex to the centre of clip space): must be within 0.1 degrees: a "
             "spot's cone and its shadow frustum share their axis");

    if (!l.shadowed) return;  // a light color alone: outside the frustum it is 1 (docs/model.md)
    // Each side plane passes through the apex; a direction u from it is inside where n . u >= 0.
    const struct {
        const char* side;
        glm::dvec3 normal;
    } sides[4] = {
        {"x = -w", w3 + x3}, {"x = +w", w3 - x3}, {"y = -w", w3 + y3}, {"y = +w", w3 - y3}};
    const char* tightest = sides[0].side;
    double room = std::numeric_limits<double>::infinity();
    for (const auto& s : sides) {
        const double sine = glm::dot(glm::normalize(s.normal), l.direction);
        const double degrees = std::asin(std::clamp(sine, -1.0, 1.0)) * kDegreesPerRadian;
        if (degrees < room) {
            room = degrees;
            tightest = s.side;
        }
    }
    if (!(l.outerConeAngleDegrees - room <= kConeDegrees))
        fail(at + ".outerConeAngleDegrees = " + num(l.outerConeAngleDegrees) +
             ": the cone reaches " + num(l.outerConeAngleDegrees - room) +
             " degrees past the side of " + matrix + "'s frustum at clip " + tightest + ", " +
             num(room) + " degrees from " + at +
             ".direction: the frustum must contain the cone (to 0.01 degrees), outside it the "
             "air would be lit unshadowed");
}

void checkDirectional(const glm::dmat4& m, const ProjectedLight& l, const std::string& at) {
    const std::string matrix = at + ".shadowViewProjection";
    const glm::dvec4 x = row(m, 0), y = row(m, 1), z = row(m, 2), w = row(m, 3);
    const glm::dvec3 across = glm::cross(glm::dvec3(x), glm::dvec3(y));
    if (!(glm::length(across) > 0.0))
        fail(matrix +
             "'s clip x and y rows are parallel (no direction keeps both): a "
             "directional light's shadow map projects along " +
             at + ".direction");
    // The axis: the direction along which clip x and y stay, as an orthographic projection's.
    glm::dvec3 axis = glm::normalize(across);
    if (!l.shadowed) {
        // A light color alone is projected the same either way along the axis: only its line
        // counts.
        const double off = degreesBetween(axis, l.direction);
        const double line = std::min(off, 180.0 - off);
        if (!(line <= kAxisDegrees))
            fail(at + ".direction is " + num(line) + " degrees off the axis of " + matrix + ", " +
                 vecText(axis) +
                 " (the direction along which its clip x and y stay): must be within 0.1 "
                 "degrees: a directional light's color is projected along its direction");
        return;
    }
    // Signed by depth: the light travels the way its shadow map's depth grows (falls with
    // shadowReversedZ). Depth's derivative along the axis where the projection puts clip
    // (0, 0, 0.5, 1), for an orthographic projection and a perspective one alike.
    const glm::dvec4 centre = glm::inverse(m) * glm::dvec4(0.0, 0.0, 0.5, 1.0);
    const double growth = glm::dot(glm::dvec3(z) - 0.5 * glm::dvec3(w), axis) * centre.w;
    if (growth < 0.0) axis = -axis;
    if (l.shadowReversedZ) axis = -axis;
    const double off = degreesBetween(axis, l.direction);
    if (!(off <= kAxisDegrees))
        fail(at + ".direction is " + num(off) + " degrees off the axis of " + matrix + ", " +
             vecText(axis) + " (the direction along which its clip x and y stay and its depth " +
             (l.shadowReversedZ ? "falls, as " + at + ".shadowReversedZ is true"
                                : "grows, as " + at + ".shadowReversedZ is false") +
             "): must be within 0.1 degrees: a directional light's shadow map looks the way its "
             "light travels");
}

}  // namespace

void checkLightProjection(const glm::mat4& m, const ProjectedLight& light, const std::string& at) {
    if (light.type == LightType::Spot)
        checkSpot(glm::dmat4(m), light, at);
    else if (light.type == LightType::Directional)
        checkDirectional(glm::dmat4(m), light, at);
}

}  // namespace lightscatter::detail
