#include "field_checks.h"

#include <charconv>
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

std::string floatText(float v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
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
    const auto low = static_cast<float>(lo), high = static_cast<float>(hi);
    if (!(v >= low && v <= high))
        fail(field + " = " + floatText(v) + ": must be in [" + floatText(low) + ", " +
             floatText(high) + "] (" + why + ")");
    return v;
}

glm::vec3 vecInRange(const Vec3& v, const std::string& field, double lo, double hi,
                     const std::string& why) {
    for (size_t i = 0; i < 3; ++i)
        inRange(v[i], field + "[" + std::to_string(i) + "]", lo, hi, why);
    return {v[0], v[1], v[2]};
}

}  // namespace lightscatter::detail
