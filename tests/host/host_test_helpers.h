// Helpers the host's test files share (the test programs compile their files in batches, so two
// files' private copies would clash).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <glm/vec3.hpp>

namespace host_test {

// Each component of `actual` within `tolerance` of `expected`'s, each reported on its own.
inline void expectVec3(const glm::vec3& actual, const glm::vec3& expected,
                       float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// A file's bytes as they are; empty when it cannot be opened.
inline std::string readAll(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace host_test
