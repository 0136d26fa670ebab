#include "image_io.h"

#include <cstdlib>
#include <stdexcept>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO_FAILURE_MESSAGES
#include <stb/stb_image_write.h>
#include <tinyexr.h>

#include "output_set.h"

namespace host {
namespace {

void checkPixels(const std::string& path, size_t have, uint32_t width, uint32_t height) {
    if (have != size_t{4} * width * height)
        throw std::runtime_error(path + ": pixel buffer does not match " + std::to_string(width) +
                                 "x" + std::to_string(height));
}

}  // namespace

bool encodePng(const std::string& path, uint32_t width, uint32_t height,
               const std::vector<uint8_t>& rgba) {
    checkPixels(path, rgba.size(), width, height);
    return stbi_write_png(path.c_str(), static_cast<int>(width), static_cast<int>(height), 4,
                          rgba.data(), static_cast<int>(width * 4)) != 0;
}

bool encodeExr(const std::string& path, uint32_t width, uint32_t height,
               const std::vector<float>& rgba) {
    checkPixels(path, rgba.size(), width, height);
    std::vector<float> rgb(size_t{3} * width * height);
    for (size_t i = 0; i < size_t{width} * height; ++i)
        for (size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = rgba[i * 4 + c];
    const char* err = nullptr;
    const int r = SaveEXR(rgb.data(), static_cast<int>(width), static_cast<int>(height), 3,
                          /*save_as_fp16=*/0, path.c_str(), &err);
    if (err) FreeEXRErrorMessage(err);
    return r == TINYEXR_SUCCESS;
}

void writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba) {
    OutputSet out;
    out.add("output", path);
    out.write(
        path, [&](const std::string& tmp) { return encodePng(tmp, width, height, rgba); }, "PNG");
    out.commit();
}

void writeExr(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgba) {
    OutputSet out;
    out.add("output", path);
    out.write(
        path, [&](const std::string& tmp) { return encodeExr(tmp, width, height, rgba); },
        "OpenEXR");
    out.commit();
}

void writeTextFile(const std::string& path, const std::string& text) {
    OutputSet out;
    out.add("output", path);
    out.writeText(path, text);
    out.commit();
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
