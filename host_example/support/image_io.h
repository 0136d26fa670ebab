#pragma once
// Image files the command line writes and reads. The encoders make a file's bytes in memory
// (callers hand them to an OutputSet, output_set.h, which checks every byte reaches the disk);
// writePng/writeExr/writeTextFile write one file on its own, through a temporary beside it that is
// renamed into place, so a failure or a signal never leaves a half-written file.
#include <cstdint>
#include <string>
#include <vector>

namespace host {

// RGBA8, row-major, top row first. Throws when the pixels do not fill width x height.
std::vector<uint8_t> encodePng(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba);
// 32-bit float linear RGB OpenEXR from RGBA floats (alpha dropped).
std::vector<uint8_t> encodeExr(uint32_t width, uint32_t height, const std::vector<float>& rgba);

void writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba);
void writeExr(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgba);
// `option` names the file in messages ("--out", "save settings").
void writeTextFile(const std::string& path, const std::string& text,
                   const std::string& option = "output");

struct FloatImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
};
FloatImage readExr(const std::string& path);

}  // namespace host
