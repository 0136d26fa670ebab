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

void checkPixels(size_t have, uint32_t width, uint32_t height) {
    if (have != size_t{4} * width * height)
        throw std::logic_error("pixel buffer does not match " + std::to_string(width) + "x" +
                               std::to_string(height));
}

void appendBytes(void* context, void* data, int size) {
    auto* bytes = static_cast<std::vector<uint8_t>*>(context);
    const auto* at = static_cast<const uint8_t*>(data);
    bytes->insert(bytes->end(), at, at + size);
}

}  // namespace

std::vector<uint8_t> encodePng(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba) {
    checkPixels(rgba.size(), width, height);
    std::vector<uint8_t> bytes;
    if (!stbi_write_png_to_func(appendBytes, &bytes, static_cast<int>(width),
                                static_cast<int>(height), 4, rgba.data(),
                                static_cast<int>(width * 4)))
        throw std::runtime_error("cannot encode a " + std::to_string(width) + "x" +
                                 std::to_string(height) + " PNG");
    return bytes;
}

std::vector<uint8_t> encodeExr(uint32_t width, uint32_t height, const std::vector<float>& rgba) {
    checkPixels(rgba.size(), width, height);
    // What tinyexr's SaveEXR does, to memory: its own file writing leaves fclose() unchecked, so a
    // disk that fills there gave a truncated reference that the benchmark's cache read back.
    const size_t pixels = size_t{width} * height;
    std::vector<float> channel[3];  // B, G, R: the order OpenEXR readers expect
    for (auto& c : channel) c.resize(pixels);
    for (size_t i = 0; i < pixels; ++i)
        for (size_t c = 0; c < 3; ++c) channel[2 - c][i] = rgba[i * 4 + c];
    float* planes[3] = {channel[0].data(), channel[1].data(), channel[2].data()};
    EXRImage image;
    InitEXRImage(&image);
    image.num_channels = 3;
    image.images = reinterpret_cast<unsigned char**>(planes);
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    EXRHeader header;
    InitEXRHeader(&header);
    header.compression_type =
        width < 16 && height < 16 ? TINYEXR_COMPRESSIONTYPE_NONE : TINYEXR_COMPRESSIONTYPE_ZIP;
    EXRChannelInfo channels[3] = {};
    for (int c = 0; c < 3; ++c) channels[c].name[0] = "BGR"[c];
    int types[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
    header.num_channels = 3;
    header.channels = channels;
    header.pixel_types = types;
    header.requested_pixel_types = types;
    unsigned char* memory = nullptr;
    const char* err = nullptr;
    const size_t size = SaveEXRImageToMemory(&image, &header, &memory, &err);
    const std::string why = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    if (size == 0 || !memory) {
        std::free(memory);
        throw std::runtime_error("cannot encode a " + std::to_string(width) + "x" +
                                 std::to_string(height) + " OpenEXR: " + why);
    }
    std::vector<uint8_t> bytes(memory, memory + size);
    std::free(memory);
    return bytes;
}

void writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba) {
    OutputSet out;
    out.add("output", path);
    out.write(path, encodePng(width, height, rgba), "PNG");
    out.commit();
}

void writeExr(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgba) {
    OutputSet out;
    out.add("output", path);
    out.write(path, encodeExr(width, height, rgba), "OpenEXR");
    out.commit();
}

void writeTextFile(const std::string& path, const std::string& text, const std::string& option) {
    OutputSet out;
    out.add(option, path);
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
