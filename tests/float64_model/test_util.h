#pragma once

#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <glm/vec3.hpp>

namespace ls::ref::test {

// Each channel within rel * |expected| + abs of the expected value.
inline ::testing::AssertionResult near3(const glm::dvec3& actual, const glm::dvec3& expected,
                                        double rel, double abs = 0.0) {
    for (int c = 0; c < 3; ++c) {
        const double tol = rel * std::abs(expected[c]) + abs;
        if (!(std::abs(actual[c] - expected[c]) <= tol)) {
            return ::testing::AssertionFailure()
                   << "channel " << c << ": actual " << actual[c] << " expected " << expected[c]
                   << " (relative difference "
                   << std::abs(actual[c] - expected[c]) / std::abs(expected[c]) << ", tolerance "
                   << tol << ")";
        }
    }
    return ::testing::AssertionSuccess();
}

inline bool finite3(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline bool nonNegative3(const glm::dvec3& v) {
    return v.x >= 0.0 && v.y >= 0.0 && v.z >= 0.0;
}

}  // namespace ls::ref::test
