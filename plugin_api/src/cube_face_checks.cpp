#include "cube_face_checks.h"

#include <cmath>

#include "field_checks.h"
#include "matrix_checks.h"

namespace lightscatter::detail {
namespace {

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

}  // namespace

glm::mat4 checkCubeFace(const Mat4& given, size_t i, const glm::vec3& light, bool reversedZ,
                        const std::string& at) {
    const std::string field = at + ".cubeFaceViewProjections[" + std::to_string(i) + "]";
    const glm::mat4 m = matrix(given, field);
    const CubeFace& f = kCubeFaces[i];
    if (conditioning(m) < 1e-9)
        fail(field + " is singular" + (allZero(given) ? " (all zero)" : "") +
             ": a point light's shadow map needs each face's world -> clip matrix (face " + f.name +
             ")");
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
                fail(field + " puts the point " + metres(dist) + " along " + f.name + " from " +
                     at + ".position behind its camera (clip w " + num(c.w) + "): face " +
                     std::to_string(i) + " must look along " + f.name + " from the light");
            const double x = c.x / c.w, y = c.y / c.w;
            if (std::fabs(x - p.u) > 1e-3 || std::fabs(y - p.v) > 1e-3) {
                if (p.u == 0 && p.v == 0)
                    fail(field + " does not look along " + f.name + " from " + at +
                         ".position: the axis " + metres(dist) + " out lands at clip " +
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

}  // namespace lightscatter::detail
