#include "matrix_checks.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>

#include "field_checks.h"

namespace lightscatter::detail {

glm::mat4 matrix(const Mat4& m, const std::string& field) {
    for (size_t i = 0; i < 16; ++i)
        if (!finite(m[i]))
            fail(field + " element " + std::to_string(i) + " is " + num(m[i]) +
                 ": matrices must be finite");
    return glm::make_mat4(m.data());
}

bool allZero(const Mat4& m) {
    return std::all_of(m.begin(), m.end(), [](float v) { return v == 0.0f; });
}

double conditioning(const glm::dmat4& d) {
    double rows = 1.0;
    for (int r = 0; r < 4; ++r) rows *= glm::length(glm::dvec4(d[0][r], d[1][r], d[2][r], d[3][r]));
    if (!(rows > 0.0)) return 0.0;
    return std::fabs(glm::determinant(d)) / rows;
}

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

void checkMatrixScale(const glm::mat4& m, const std::string& field) {
    float largest = 0.0f;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) largest = std::max(largest, std::fabs(m[c][r]));
    if (!(largest >= 1e-20f && largest <= 1e20f))
        fail(field + " has its largest element at " + num(largest) +
             ": must be within [1e-20, 1e+20] (a clip matrix may be scaled freely: scale it)");
}

}  // namespace lightscatter::detail
