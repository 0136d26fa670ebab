#include "image_io.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO_FAILURE_MESSAGES
#include <stb/stb_image_write.h>
#include <tinyexr.h>

#include <cstdlib>

namespace host {

void writeAtomically(const std::string& path, const std::function<bool(const std::string&)>& write,
                     const char* what) {
    const std::string tmp = path + ".partial";
    if (!write(tmp)) {
        std::remove(tmp.c_str());
        throw std::runtime_error(path + ": cannot write " + what + " (is the directory writable?)");
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::remove(tmp.c_str());
        throw std::runtime_error(path + ": cannot move the finished " + what + " into place: " +
                                 ec.message());
    }
}

void writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba) {
    if (rgba.size() != size_t{4} * width * height)
        throw std::runtime_error(path + ": pixel buffer does not match " + std::to_string(width) +
                                 "x" + std::to_string(height));
    writeAtomically(path, [&](const std::string& tmp) {
        return stbi_write_png(tmp.c_str(), static_cast<int>(width), static_cast<int>(height), 4,
                              rgba.data(), static_cast<int>(width * 4)) != 0;
    }, "PNG");
}

void writeExr(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgba) {
    if (rgba.size() != size_t{4} * width * height)
        throw std::runtime_error(path + ": pixel buffer does not match " + std::to_string(width) +
                                 "x" + std::to_string(height));
    std::vector<float> rgb(size_t{3} * width * height);
    for (size_t i = 0; i < size_t{width} * height; ++i)
        for (size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = rgba[i * 4 + c];
    writeAtomically(path, [&](const std::string& tmp) {
        const char* err = nullptr;
        const int r = SaveEXR(rgb.data(), static_cast<int>(width), static_cast<int>(height), 3,
                              /*save_as_fp16=*/0, tmp.c_str(), &err);
        if (err) FreeEXRErrorMessage(err);
        return r == TINYEXR_SUCCESS;
    }, "OpenEXR");
}

FloatImage readExr(const std::string& path) {
    float* data = nullptr;
    int w = 0, h = 0;
    const char* err = nullptr;
    if (LoadEXR(&data, &w, &h, path.c_str(), &err) != TINYEXR_SUCCESS) {
        const std::string why = err ? err : "unknown error";
        if (err) FreeEXRErrorMessage(err);
        throw std::runtime_error(path + ": cannot read OpenEXR: " + why);
    }
    FloatImage img;
    img.width = static_cast<uint32_t>(w);
    img.height = static_cast<uint32_t>(h);
    img.rgba.assign(data, data + size_t{4} * img.width * img.height);
    std::free(data);
    return img;
}

}  // namespace host
