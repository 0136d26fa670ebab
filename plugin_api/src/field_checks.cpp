#include "field_checks.h"

#include <cmath>
#include <cstdio>

namespace lightscatter::detail {

void fail(const std::string& message) {
    throw InvalidInput("lightscatter: " + message);
}

std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string metres(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4g m", v);
    return buf;
}

std::string rangeText(double lo, double hi) {
    return "[" + num(lo) + ", " + num(hi) + "]";
}

bool finite(float v) {
    return std::isfinite(v);
}

glm::vec3 vec(const Vec3& v, const std::string& field) {
    for (size_t i = 0; i < 3; ++i)
        if (!finite(v[i])) fail(field + " has a non-finite component (" + num(v[i]) + ")");
    return {v[0], v[1], v[2]};
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

}  // namespace lightscatter::detail
