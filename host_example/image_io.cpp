#include "image_io.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO_FAILURE_MESSAGES
#include <stb/stb_image_write.h>

namespace host {

void writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba) {
    if (rgba.size() != size_t{4} * width * height)
        throw std::runtime_error(path + ": pixel buffer does not match " + std::to_string(width) +
                                 "x" + std::to_string(height));
    const std::string tmp = path + ".partial";
    if (!stbi_write_png(tmp.c_str(), static_cast<int>(width), static_cast<int>(height), 4,
                        rgba.data(), static_cast<int>(width * 4))) {
        std::remove(tmp.c_str());
        throw std::runtime_error(path + ": cannot write PNG (is the directory writable?)");
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::remove(tmp.c_str());
        throw std::runtime_error(path + ": cannot move the finished PNG into place: " + ec.message());
    }
}

}  // namespace host
