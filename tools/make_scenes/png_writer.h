#pragma once
// A minimal PNG encoder (RGBA8, zlib "stored" blocks): enough for the small procedural textures,
// with byte-for-byte deterministic output and no image library.
#include <cstdint>
#include <string>
#include <vector>

namespace make_scenes {

std::vector<uint8_t> encodePng(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba);

}  // namespace make_scenes
