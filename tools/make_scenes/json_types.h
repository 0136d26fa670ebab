#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace make_scenes {

// Keys in insertion order and single-precision numbers: floats print as the shortest text that
// reads back as the same float ("0.68", not "0.6800000071525574"), which is also what glTF accessor
// min/max must match.
using Json = nlohmann::basic_json<nlohmann::ordered_map, std::vector, std::string, bool,
                                  std::int64_t, std::uint64_t, float>;

}  // namespace make_scenes
