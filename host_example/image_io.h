#pragma once
// Image files the command line writes. Each function writes to a temporary file beside the target
// and renames it into place, so a failure never leaves a half-written image.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace host {

// RGBA8, row-major, top row first.
void writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba);

// 32-bit float linear RGB OpenEXR from RGBA floats (alpha dropped).
void writeExr(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgba);

struct FloatImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
};
FloatImage readExr(const std::string& path);

// Writes `path` by writing `path.partial` with `write` and renaming it into place.
void writeAtomically(const std::string& path, const std::function<bool(const std::string&)>& write,
                     const char* what);

}  // namespace host
