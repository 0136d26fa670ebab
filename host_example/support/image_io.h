#pragma once
// Image files the command line writes and reads. The encoders write straight to a path (callers
// give them a temporary: output_set.h); writePng/writeExr/writeTextFile write one file on its own,
// through a temporary beside it that is renamed into place, so a failure or a signal never leaves
// a half-written file.
#include <cstdint>
#include <string>
#include <vector>

namespace host {

// RGBA8, row-major, top row first. False when the file could not be written.
bool encodePng(const std::string& path, uint32_t width, uint32_t height,
               const std::vector<uint8_t>& rgba);
// 32-bit float linear RGB OpenEXR from RGBA floats (alpha dropped).
bool encodeExr(const std::string& path, uint32_t width, uint32_t height,
               const std::vector<float>& rgba);

void writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba);
void writeExr(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgba);
void writeTextFile(const std::string& path, const std::string& text);

struct FloatImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
};
FloatImage readExr(const std::string& path);

}  // namespace host
