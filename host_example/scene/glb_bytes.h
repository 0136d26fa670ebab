#pragma once
// What the glTF mesh loader and the glTF lights reader both need to read a .glb's header, and the
// cap on a glTF file's size they share.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "scene/input_file.h"

namespace host::glb {

inline constexpr uint32_t kMagic = 0x46546C67u;      // "glTF"
inline constexpr uint32_t kJsonChunk = 0x4E4F534Au;  // "JSON"
inline constexpr uint32_t kBinChunk = 0x004E4942u;   // "BIN\0"
// A .gltf/.glb, and each buffer or image it references, is read whole; beyond this it is refused.
inline constexpr uint64_t kFileCap = 2 * kGiB;

// The little-endian word at `at` (the caller has checked that 4 bytes are there).
inline uint32_t readU32(const std::vector<unsigned char>& bytes, size_t at) {
    return uint32_t{bytes[at]} | uint32_t{bytes[at + 1]} << 8 | uint32_t{bytes[at + 2]} << 16 |
           uint32_t{bytes[at + 3]} << 24;
}

}  // namespace host::glb
