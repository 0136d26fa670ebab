#pragma once
// Image files the command line writes. Each function writes to a temporary file beside the target
// and renames it into place, so a failure never leaves a half-written image.
#include <cstdint>
#include <string>
#include <vector>

namespace host {

// RGBA8, row-major, top row first.
void writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba);

}  // namespace host
