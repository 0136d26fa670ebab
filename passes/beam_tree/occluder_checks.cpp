#include "occluder_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ls::beam {
namespace {

// Numbers and non-finite components are written as the plugin writes them for the engine's other
// fields: a refusal reads alike whichever folder gives it.
std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string nonFinite(const glm::vec3& v, const std::string& field) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i])) return field + " has a non-finite component (" + num(v[i]) + ")";
    return {};
}

std::string refuseBox(const GivenBox& b, const std::string& field, float maxLength) {
    const glm::vec3 c = b.center, h = b.halfExtents;
    if (std::string why = nonFinite(c, field + ".center"); !why.empty()) return why;
    if (std::string why = nonFinite(h, field + ".halfExtents"); !why.empty()) return why;
    for (int i = 0; i < 3; ++i) {
        if (!(h[i] > 0.0f))
            return field + ".halfExtents[" + std::to_string(i) + "] = " + num(h[i]) +
                   ": must be > 0";
        // The beam tree works in double, but its pyramids end on the shaders' float lengths.
        if (std::fabs(c[i]) > maxLength || h[i] > maxLength)
            return field + (std::fabs(c[i]) > maxLength ? ".center[" : ".halfExtents[") +
                   std::to_string(i) + "] = " + num(std::fabs(c[i]) > maxLength ? c[i] : h[i]) +
                   ": must be within +-" + num(maxLength) + " m (limits::kMaxLength)";
    }
    const std::array<glm::vec3, 3>& a = b.axes;
    for (int i = 0; i < 3; ++i) {
        const std::string axis = field + ".axes[" + std::to_string(i) + "]";
        if (std::string why = nonFinite(a[i], axis); !why.empty()) return why;
        if (std::fabs(glm::length(a[i]) - 1.0f) > 1e-3f)
            return axis + " has length " + num(glm::length(a[i])) + ": must be unit";
    }
    for (int i = 0; i < 3; ++i)
        if (std::fabs(glm::dot(a[i], a[(i + 1) % 3])) > 1e-3f)
            return field + ".axes[" + std::to_string(i) + "] and [" + std::to_string((i + 1) % 3) +
                   "] are not orthogonal (dot " + num(glm::dot(a[i], a[(i + 1) % 3])) + ")";
    return {};
}

// Every corner of `inner` within `outer` (to a millimetre or 1e-4 of its size).
bool boxInside(const GivenBox& inner, const GivenBox& outer) {
    const glm::vec3 oh = outer.halfExtents;
    const float tolerance = std::max(1e-3f, 1e-4f * glm::length(oh));
    for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 p = inner.center;
        for (int i = 0; i < 3; ++i) {
            const float s = (corner >> i & 1) ? 1.0f : -1.0f;
            p += s * inner.halfExtents[i] * inner.axes[static_cast<size_t>(i)];
        }
        for (int i = 0; i < 3; ++i)
            if (std::fabs(glm::dot(p - outer.center, outer.axes[static_cast<size_t>(i)])) >
                oh[i] + tolerance)
                return false;
    }
    return true;
}

OrientedBox toBox(const GivenBox& b) {
    OrientedBox o;
    o.center = glm::dvec3(b.center);
    for (int i = 0; i < 3; ++i)
        o.axes[i] = glm::normalize(glm::dvec3(b.axes[static_cast<size_t>(i)]));
    o.halfExtents = glm::dvec3(b.halfExtents);
    return o;
}

}  // namespace

std::string refuseOccluders(const std::vector<GivenOccluder>& occluders, size_t maxCount,
                            float maxLength) {
    if (occluders.size() > maxCount)
        return "occluders has " + std::to_string(occluders.size()) + " entries: at most " +
               std::to_string(maxCount);
    for (size_t i = 0; i < occluders.size(); ++i) {
        const std::string field = "occluders[" + std::to_string(i) + "]";
        if (std::string why = refuseBox(occluders[i].outer, field + ".outer", maxLength);
            !why.empty())
            return why;
        if (!occluders[i].inner) continue;
        if (std::string why = refuseBox(*occluders[i].inner, field + ".inner", maxLength);
            !why.empty())
            return why;
        if (!boxInside(*occluders[i].inner, occluders[i].outer))
            return field + ".inner is not inside " + field +
                   ".outer: an inner box lies within the object, and the outer box encloses it";
    }
    return {};
}

std::vector<Occluder> toOccluders(const std::vector<GivenOccluder>& occluders) {
    std::vector<Occluder> out;
    out.reserve(occluders.size());
    for (const GivenOccluder& o : occluders) {
        Occluder b;
        b.outer = toBox(o.outer);
        if (o.inner) b.inner = toBox(*o.inner);
        out.push_back(b);
    }
    return out;
}

}  // namespace ls::beam
